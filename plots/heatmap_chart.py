"""dtoadq heat-map chart: one quantity over a two-parameter grid for several methods, panels side
by side on one colour scale that diverges at --centre.
Reads the table written by plots/heatmap_chart.cpp (panel,x,y,value)."""
import plot_common
from plot_common import plt
from matplotlib.colors import TwoSlopeNorm


def main():
    parser = plot_common.argument_parser()
    parser.add_argument("--title", default="")
    parser.add_argument("--x-label", default="x")
    parser.add_argument("--y-label", default="y")
    parser.add_argument("--value-label", default="value")
    parser.add_argument("--centre", type=float, default=1.0)
    args = parser.parse_args()

    panels, names = {}, []
    for r in plot_common.read_rows(args.data):
        if r["panel"] not in panels:
            names.append(r["panel"])
            panels[r["panel"]] = {}
        panels[r["panel"]][(float(r["x"]), float(r["y"]))] = float(r["value"])
    xs = sorted({x for p in panels.values() for x, _ in p})
    ys = sorted({y for p in panels.values() for _, y in p})
    values = [v for p in panels.values() for v in p.values()]
    low, high = min(values), max(values)
    # the scale diverges at the centre; a side with nothing on it still gets a sliver, so the norm is defined
    span = max(high - args.centre, args.centre - low, 1e-3)
    norm = TwoSlopeNorm(vcenter=args.centre, vmin=min(low, args.centre - 0.05 * span), vmax=max(high, args.centre + 0.05 * span))
    fig, axes = plt.subplots(1, len(names), figsize=(4.2 * len(names) + 1.2, 4.2), squeeze=False)
    for ax, name in zip(axes[0], names):
        grid = [[panels[name][(x, y)] for x in xs] for y in ys]
        image = ax.pcolormesh(xs, ys, grid, cmap="RdBu_r", norm=norm, shading="nearest")
        ax.set_title(name, fontsize=10)
        ax.set_xlabel(args.x_label)
        ax.set_ylabel(args.y_label)
    fig.colorbar(image, ax=axes[0].tolist(), label=args.value_label, shrink=0.9)
    fig.suptitle(args.title, fontsize=11)
    plot_common.save(fig, args.out, dpi=100)


if __name__ == "__main__":
    main()
