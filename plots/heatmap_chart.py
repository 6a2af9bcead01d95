"""dtoadq heat-map chart: one quantity over a two-parameter grid for several methods, panels side
by side on one colour scale that diverges at --centre (only its upper half when no value lies below).
Reads the table written by plots/heatmap_chart.cpp (panel,x,y,value)."""
import math

import numpy

import plot_common
from plot_common import plt
from matplotlib.colors import ListedColormap, Normalize, TwoSlopeNorm
from matplotlib.ticker import FormatStrFormatter, LogLocator, NullLocator


def linear_edges(centres):
    """The edges of cells around increasing centres, meeting halfway (matplotlib's shading="nearest")."""
    if len(centres) == 1:
        return [centres[0] - 0.5, centres[0] + 0.5]
    mids = [(a + b) / 2 for a, b in zip(centres, centres[1:])]
    return [2 * centres[0] - mids[0]] + mids + [2 * centres[-1] - mids[-1]]


def log_edges(centres):
    """The same in log space: cells meet at geometric means."""
    return [math.exp(e) for e in linear_edges([math.log(c) for c in centres])]


def main():
    parser = plot_common.argument_parser()
    parser.add_argument("--title", default="")
    parser.add_argument("--x-label", default="x")
    parser.add_argument("--y-label", default="y")
    parser.add_argument("--value-label", default="value")
    parser.add_argument("--centre", type=float, default=1.0)
    parser.add_argument("--log-x", action="store_true")
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
    if low >= args.centre:
        # every value on the upper side (a share of rays lost, 0 at best): that half of the scale alone, white at the centre
        cmap = ListedColormap(plt.get_cmap("RdBu_r")(numpy.linspace(0.5, 1.0, 256)))
        norm = Normalize(vmin=args.centre, vmax=max(high, args.centre + 1e-3))
    else:
        # the scale diverges at the centre; a side with nothing on it still gets a sliver, so the norm is defined
        cmap = "RdBu_r"
        span = max(high - args.centre, args.centre - low, 1e-3)
        norm = TwoSlopeNorm(vcenter=args.centre, vmin=min(low, args.centre - 0.05 * span), vmax=max(high, args.centre + 0.05 * span))
    fig, axes = plt.subplots(1, len(names), figsize=(4.2 * len(names) + 1.2, 4.2), squeeze=False)
    for ax, name in zip(axes[0], names):
        grid = [[panels[name][(x, y)] for x in xs] for y in ys]
        if args.log_x:
            # cells that meet halfway in log x: linear midpoints can fall at or below 0
            image = ax.pcolormesh(log_edges(xs), linear_edges(ys), grid, cmap=cmap, norm=norm, shading="flat")
        else:
            image = ax.pcolormesh(xs, ys, grid, cmap=cmap, norm=norm, shading="nearest")
        if args.log_x:
            ax.set_xscale("log")
            ax.xaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 3.0, 5.0)))
            ax.xaxis.set_major_formatter(FormatStrFormatter("%g"))
            ax.xaxis.set_minor_locator(NullLocator())
        ax.set_title(name, fontsize=10)
        ax.set_xlabel(args.x_label)
        ax.set_ylabel(args.y_label)
    fig.colorbar(image, ax=axes[0].tolist(), label=args.value_label, shrink=0.9)
    fig.suptitle(args.title, fontsize=11)
    plot_common.save(fig, args.out, dpi=100)


if __name__ == "__main__":
    main()
