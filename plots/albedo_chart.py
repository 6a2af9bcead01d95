"""dtoadq albedo chart: directional albedo against incident angle, r, g, b per material.
Reads the table written by plots/albedo_chart.cpp (material,theta,a_r,a_g,a_b,se_r,se_g,se_b)."""
import math

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

import plot_common
from plot_common import plt

CHANNELS = (("r", "#d62728", "red"), ("g", "#2ca02c", "green"), ("b", "#1f77b4", "blue"))


def load(path):
    names, curves = [], {}
    for r in plot_common.read_rows(path):
        if r["material"] not in curves:
            names.append(r["material"])
            curves[r["material"]] = []
        curves[r["material"]].append([float(r[k]) for k in ("theta", "a_r", "a_g", "a_b", "se_r", "se_g", "se_b")])
    return names, {n: np.array(c) for n, c in curves.items()}


def main():
    parser = plot_common.argument_parser()
    parser.add_argument("--phi-in", type=float, default=0.0)
    parser.add_argument("--samples", type=int, required=True)
    args = parser.parse_args()

    names, curves = load(args.data)
    cols = min(len(names), 4)
    rows = math.ceil(len(names) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(max(3.9 * cols + 0.6, 9.0), 3.1 * rows + 1.4), squeeze=False, sharex=True)
    for k, ax in enumerate(axes.flat):
        if k >= len(names):
            ax.set_visible(False)
            continue
        c = curves[names[k]]
        theta = c[:, 0]
        # each panel its own range, so a material that creates energy does not flatten the others
        top = max(1.1, float((c[:, 1:4] + 2 * c[:, 4:7]).max()) * 1.05)
        ax.axhspan(1.0, top, color="#d62728", alpha=0.06, lw=0)  # above 1: the BSDF creates energy
        ax.axhline(1.0, color="black", ls="--", lw=1)
        for j, (_, colour, _) in enumerate(CHANNELS):
            a, se = c[:, 1 + j], c[:, 4 + j]
            ax.fill_between(theta, a - 2 * se, a + 2 * se, color=colour, alpha=0.2, lw=0)
            ax.plot(theta, a, color=colour, lw=1.6)
        ax.set_title(names[k], fontsize=10)
        ax.set_xlim(0, 90)
        ax.set_ylim(0, top)
        ax.set_xticks(range(0, 91, 15))
        ax.grid(True, color="0.9", lw=0.6)
        ax.tick_params(labelsize=8)
        if k % cols == 0:
            ax.set_ylabel("directional albedo", fontsize=9)
        if k >= len(names) - cols:
            ax.set_xlabel("incident angle θi (degrees)", fontsize=9)
            ax.xaxis.set_tick_params(labelbottom=True)
    handles = [Line2D([], [], color=colour, lw=2, label=label) for _, colour, label in CHANNELS]
    handles += [Patch(color="0.6", alpha=0.4, label="± 2 standard errors"),
                Line2D([], [], color="black", ls="--", lw=1, label="1: all light scattered (energy conservation)")]
    wide = fig.get_figwidth() > 8.5
    fig.legend(handles=handles, loc="lower center", ncol=len(handles) if wide else 3, fontsize=9, frameon=False)
    fig.suptitle("Directional albedo  a(ωi) = ∫ f(ωi, ωo) |cos θo| dωo\n%d importance samples per angle, φi = %g°, delta lobes included"
                 % (args.samples, args.phi_in), fontsize=11)
    legend_in = 0.35 if wide else 0.6
    fig.tight_layout(rect=(0, legend_in / fig.get_figheight(), 1, 1 - 0.02 / fig.get_figheight()))
    plot_common.save(fig, args.out, dpi=110)


if __name__ == "__main__":
    main()
