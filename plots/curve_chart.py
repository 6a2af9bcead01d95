"""dtoadq curve chart: measured curves and reference levels (dashed) of one quantity against
another, log-log.
Reads the table written by plots/curve_chart.cpp (curve,kind,x,y)."""
import plot_common
from plot_common import plt


def main():
    parser = plot_common.argument_parser()
    parser.add_argument("--title", default="")
    parser.add_argument("--x-label", default="x")
    parser.add_argument("--y-label", default="y")
    args = parser.parse_args()

    names, curves = [], {}
    for r in plot_common.read_rows(args.data):
        if r["curve"] not in curves:
            names.append(r["curve"])
            curves[r["curve"]] = (r["kind"] == "reference", [], [])
        curves[r["curve"]][1].append(float(r["x"]))
        curves[r["curve"]][2].append(float(r["y"]))
    measured = [n for n in names if not curves[n][0]]
    references = [n for n in names if curves[n][0]]
    colours = plot_common.material_colours(len(measured))
    markers = "osD^vP*Xh<>"
    fig, ax = plt.subplots(figsize=(7.5, 5.2))
    for k, name in enumerate(measured):
        _, x, y = curves[name]
        ax.plot(x, y, color=colours[k], marker=markers[k % len(markers)], ms=5, lw=1.6, label=name)
    greys = ["0.15", "0.45", "0.65"]
    dashes = ["--", ":", "-."]
    for k, name in enumerate(references):
        _, x, y = curves[name]
        ax.plot(x, y, color=greys[k % len(greys)], ls=dashes[k % len(dashes)], lw=1.2, label=name)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(args.x_label)
    ax.set_ylabel(args.y_label)
    ax.grid(True, which="major", color="0.85", lw=0.6)
    ax.grid(True, which="minor", color="0.93", lw=0.4)
    ax.legend(fontsize=8, frameon=False)
    ax.set_title(args.title, fontsize=11)
    fig.tight_layout()
    plot_common.save(fig, args.out, dpi=110)


if __name__ == "__main__":
    main()
