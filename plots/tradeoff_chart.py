"""dtoadq trade-off chart: one labelled point per setting, the time of one sample per pixel against
the error the setting causes, with the band below which an error is noise.
Reads the table written by plots/tradeoff_chart.cpp (setting,seconds,error)."""
import plot_common
from plot_common import plt


def main():
    parser = plot_common.argument_parser()
    parser.add_argument("--title", default="")
    parser.add_argument("--error-label", default="error")
    parser.add_argument("--noise", type=float, default=0.0)
    args = parser.parse_args()

    rows = list(plot_common.read_rows(args.data))
    colours = plot_common.material_colours(len(rows))
    fig, ax = plt.subplots(figsize=(9.0, 5.2))
    times_ms = [1000.0 * float(r["seconds"]) for r in rows]
    errors = [float(r["error"]) for r in rows]
    markers = "osD^vP*Xh<>"
    # settings often tie (the same error, nearly the same time): a legend names them, not labels on top of each other
    for k, r in enumerate(rows):
        ax.plot(times_ms[k], errors[k], markers[k % len(markers)], color=colours[k], ms=8, alpha=0.85, label=r["setting"])
    if args.noise > 0:
        ax.axhspan(0, args.noise, color="0.88", zorder=0, label="noise level: errors below are not told from noise")
    ax.legend(fontsize=8, frameon=False, loc="upper left", bbox_to_anchor=(1.02, 1.0))
    ax.set_xlim(0, max(times_ms) * 1.25)
    ax.set_ylim(0, max(max(errors), args.noise) * 1.25 or 1)
    ax.set_xlabel("time per sample per pixel (ms)")
    ax.set_ylabel(args.error_label)
    ax.grid(True, color="0.9", lw=0.6)
    ax.set_title(args.title or "Time against error", fontsize=11)
    fig.tight_layout()
    plot_common.save(fig, args.out, dpi=110)


if __name__ == "__main__":
    main()
