"""dtoadq speed-accuracy chart: error of a render against a reference as a function of render time,
log-log, one line per sampling strategy, with a slope -1/2 line (the Monte Carlo rate).
Reads the table written by plots/speed_accuracy_chart.cpp (series,seconds,rmse)."""
import math

import plot_common
from plot_common import plt


def load(path):
    names, points = [], {}
    for r in plot_common.read_rows(path):
        if r["series"] not in points:
            names.append(r["series"])
            points[r["series"]] = ([], [])
        points[r["series"]][0].append(float(r["seconds"]))
        points[r["series"]][1].append(float(r["rmse"]))
    return names, points


def main():
    parser = plot_common.argument_parser()
    parser.add_argument("--title", default="")
    parser.add_argument("--error-label", default="RMSE against the reference")
    args = parser.parse_args()

    names, points = load(args.data)
    colours = plot_common.material_colours(len(names))
    markers = "osD^vP*Xh<>"
    fig, ax = plt.subplots(figsize=(7.5, 5.2))
    for k, name in enumerate(names):
        t, e = points[name]
        ax.plot(t, e, color=colours[k], marker=markers[k % len(markers)], ms=5, lw=1.6, label=name)

    # the reference slope through the geometric centre of all points, across the whole time range
    all_t = [x for n in names for x in points[n][0]]
    all_e = [y for n in names for y in points[n][1]]
    log_t = sum(math.log(x) for x in all_t) / len(all_t)
    log_e = sum(math.log(y) for y in all_e) / len(all_e)
    t0, t1 = min(all_t), max(all_t)
    if t1 <= t0:
        t0, t1 = t0 / 2, t1 * 2
    slope_t = [t0, t1]
    slope_e = [math.exp(log_e - 0.5 * (math.log(x) - log_t)) for x in slope_t]
    ax.plot(slope_t, slope_e, color="black", ls="--", lw=1, label="slope −1/2 (error ∝ 1/√time)")

    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("render time (seconds)")
    ax.set_ylabel(args.error_label)
    ax.grid(True, which="major", color="0.85", lw=0.6)
    ax.grid(True, which="minor", color="0.93", lw=0.4)
    ax.legend(fontsize=9, frameon=False)
    ax.set_title(args.title or "Error against render time", fontsize=11)
    fig.tight_layout()
    plot_common.save(fig, args.out, dpi=110)


if __name__ == "__main__":
    main()
