"""dtoadq fit chart: measured (solid) against fitted (dashed) lobes in the plane of incidence at
several incident angles, with the lobe plot's radial scale, and the fit's error over
(theta_h, theta_d). Reads lobes.csv and error_map.csv written by plots/fit_chart.cpp."""
import math
import os

import numpy as np

import plot_common
from lobe_plot import RadialScale
from plot_common import plt


def main():
    parser = plot_common.argument_parser()
    parser.add_argument("--measured", required=True)
    parser.add_argument("--fitted", required=True)
    parser.add_argument("--error", type=float, required=True)
    args = parser.parse_args()

    curves = {}
    for r in plot_common.read_rows(os.path.join(args.data, "lobes.csv")):
        c = curves.setdefault(float(r["theta_in_deg"]), ([], [], []))
        c[0].append(float(r["angle_deg"]))
        c[1].append(float(r["measured"]))
        c[2].append(float(r["fitted"]))
    rows = plot_common.read_rows(os.path.join(args.data, "error_map.csv"))
    theta_h = sorted({float(r["theta_h_deg"]) for r in rows})
    theta_d = sorted({float(r["theta_d_deg"]) for r in rows})
    grid = np.full((len(theta_h), len(theta_d)), np.nan)
    index_h = {v: i for i, v in enumerate(theta_h)}
    index_d = {v: i for i, v in enumerate(theta_d)}
    for r in rows:
        grid[index_h[float(r["theta_h_deg"])], index_d[float(r["theta_d_deg"])]] = float(r["error"])

    angles = sorted(curves)
    fig = plt.figure(figsize=(4.0 * len(angles) + 5.0, 4.6))
    for k, theta_in in enumerate(angles):
        angle, measured, fitted = (np.array(v) for v in curves[theta_in])
        scale = RadialScale([max(measured.max(), fitted.max())], "auto")
        ax = fig.add_subplot(1, len(angles) + 1, k + 1, projection="polar")
        ax.set_theta_zero_location("N")
        ax.set_theta_direction(-1)  # the mirror side on the right, as in the lobe plot
        ax.set_thetamin(-90)
        ax.set_thetamax(90)
        ax.plot(np.radians(angle), scale.radius(measured), color="black", lw=1.6, label="measured")
        ax.plot(np.radians(angle), scale.radius(fitted), color="#d62728", lw=1.3, ls="--", label="fitted")
        ax.plot([-math.radians(theta_in)] * 2, [0, scale.top], color="#888888", lw=0.8)  # the incident direction
        ax.set_rmax(scale.top)
        ax.tick_params(axis="y", labelsize=7)
        ticks = scale.ticks()
        if ticks:
            ax.set_rticks(ticks[0])
            ax.set_yticklabels(ticks[1], fontsize=7)
        ax.set_title("theta_in %g" % theta_in + (" (log radius)" if scale.log else ""), fontsize=10)
        if k == 0:
            ax.legend(loc="lower left", fontsize=8, bbox_to_anchor=(-0.1, -0.15))
    ax = fig.add_subplot(1, len(angles) + 1, len(angles) + 1)
    mesh = ax.pcolormesh(theta_d, theta_h, grid, shading="nearest", cmap="magma")
    fig.colorbar(mesh, ax=ax, label="log-space RMSE")
    ax.set_xlabel("theta_d (degrees)")
    ax.set_ylabel("theta_h (degrees)")
    ax.set_title("error over (theta_h, theta_d)", fontsize=10)
    fig.suptitle("%s fitted to %s: error %.3g (luminance of f cos theta_o, plane of incidence)"
                 % (args.fitted, os.path.basename(args.measured), args.error), fontsize=11)
    fig.tight_layout()
    plot_common.save(fig, args.out, 110)


if __name__ == "__main__":
    main()
