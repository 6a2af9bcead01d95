"""dtoadq lobe plot: a polar slice through the plane of incidence and a 3D lobe, side by side.
Reads materials.csv, plane.csv, surface.csv and deltas.csv written by plots/lobe_plot.cpp."""
import math
import os

import numpy as np
from matplotlib.lines import Line2D

import plot_common
from plot_common import plt


class RadialScale:
    """Maps a lobe value to a plotted radius, linear or logarithmic. `auto` picks log when the
    materials' peaks differ by more than 20x, so a dim lobe is not flattened by a bright one; the
    log floor keeps two decades of the dimmest lobe and at most five below the brightest."""

    def __init__(self, peaks, mode):
        lit = [p for p in peaks if p > 0]
        self.empty = not lit  # only delta lobes: the radius means nothing
        self.peak = max(lit) if lit else 1.0
        dimmest = min(lit) if lit else 1.0
        self.log = mode == "log" or (mode == "auto" and self.peak > 20 * dimmest)
        self.floor = max(self.peak * 1e-5, min(dimmest * 1e-2, self.peak * 1e-3))

    def radius(self, v):
        v = np.asarray(v, dtype=float)
        if not self.log:
            return v
        return np.log10(np.maximum(v, self.floor) / self.floor)

    @property
    def top(self):
        return float(self.radius(self.peak)) * 1.08

    def ticks(self):
        """Radial tick positions and their labels in value units."""
        if not self.log:
            return None
        first = math.ceil(math.log10(self.floor))
        values = [10.0 ** k for k in range(first, math.floor(math.log10(self.peak)) + 1)]
        values = [v for v in values if self.radius(v) > 0.5]  # none crowded at the origin
        return [float(self.radius(v)) for v in values], ["%g" % v for v in values]


def load(folder):
    materials = plot_common.read_rows(os.path.join(folder, "materials.csv"))
    names = [m["name"] for m in materials]
    transmits = [m["transmits"] == "1" for m in materials]
    plane = [([], []) for _ in materials]
    for r in plot_common.read_rows(os.path.join(folder, "plane.csv")):
        i = int(r["material"])
        plane[i][0].append(float(r["angle_deg"]))
        plane[i][1].append(float(r["value"]))
    surface = [[] for _ in materials]
    for r in plot_common.read_rows(os.path.join(folder, "surface.csv")):
        surface[int(r["material"])].append((float(r["theta_deg"]), float(r["phi_deg"]), float(r["value"])))
    deltas = [[] for _ in materials]
    for r in plot_common.read_rows(os.path.join(folder, "deltas.csv")):
        deltas[int(r["material"])].append(r)
    return names, transmits, plane, surface, deltas


def weight_text(r):
    w = [float(r["w_r"]), float(r["w_g"]), float(r["w_b"])]
    if max(w) - min(w) < 5e-4:
        return "%.3g" % w[0]
    return "(%.2g, %.2g, %.2g)" % tuple(w)


def draw_polar(ax, args, names, transmits, plane, deltas, colours, scale):
    ax.set_theta_zero_location("N")
    ax.set_theta_direction(-1)  # positive angles towards the mirror side, on the right
    full = any(transmits)
    if full:
        ticks = list(range(-150, 181, 30))
        ax.set_thetamin(-180)
        ax.set_thetamax(180)
    else:
        ax.set_thetamin(-90)
        ax.set_thetamax(90)
        ticks = list(range(-90, 91, 30))
    ax.set_xticks([math.radians(t) for t in ticks])
    ax.set_xticklabels(["%d°" % t for t in ticks])
    for i, name in enumerate(names):
        angles, values = plane[i]
        ax.plot(np.radians(angles), scale.radius(values), color=colours[i], lw=1.8, label=name)
    top = scale.top
    ax.set_ylim(0, top)
    t = scale.ticks()
    if scale.empty:
        ax.set_yticklabels([])
    elif t:
        ax.set_yticks(t[0])
        ax.set_yticklabels(t[1])
    ax.tick_params(axis="y", labelsize=8)
    ax.set_rlabel_position(-100 if full else 100)
    # the surface, and the incoming light as an arrow towards the origin
    for side in (-90, 90):
        ax.plot([math.radians(side)] * 2, [0, top], color="0.25", lw=2.5, solid_capstyle="butt")
    ax.annotate("", xy=(0, 0), xytext=(math.radians(-args.theta_in), top * 0.98),
                arrowprops=dict(arrowstyle="-|>", color="black", lw=2, mutation_scale=18))
    ax.text(math.radians(-args.theta_in - 4), top * 0.8, "incident\nθi = %g°" % args.theta_in, ha="right", va="center",
            fontsize=9)
    # arrows of several materials' deltas get different lengths, so their labels do not collide
    with_deltas = [i for i, lobes in enumerate(deltas) if lobes]
    for n, i in enumerate(with_deltas):
        for r in deltas[i]:
            if r["in_plane"] != "1":
                continue
            a = math.radians(float(r["plane_angle_deg"]))
            tip = top * (0.9 - 0.5 * n / max(len(with_deltas), 1))
            ax.annotate("", xy=(a, tip), xytext=(0, 0),
                        arrowprops=dict(arrowstyle="-|>", color=colours[i], lw=2, ls="--", mutation_scale=16))
            ax.text(a, tip * 0.93 + top * 0.07, "δ " + weight_text(r), color=colours[i], fontsize=8,
                    ha="center", va="center", bbox=dict(fc="white", ec="none", alpha=0.8, pad=0.5))
    title = ("Plane of incidence (φo = %g° and %g°)\nradius: luminance of f(ωi, ωo)·|cos θo| in 1/sr, %s scale"
             % (args.phi_in % 360, (args.phi_in + 180) % 360, "log" if scale.log else "linear"))
    if full:
        ax.set_title(title, fontsize=11, pad=22)
    else:
        # matplotlib fits the half disc in the middle of a square box: y from 0.25 to 0.75
        ax.text(0.5, 0.8, title, transform=ax.transAxes, ha="center", va="bottom", fontsize=11)


def draw_3d(ax, args, names, transmits, surface, deltas, colours, scale):
    extent = scale.top
    for i, points in enumerate(surface):
        p = np.array(points)
        thetas = np.unique(p[:, 0])
        phis = np.unique(p[:, 1])
        r = scale.radius(p[:, 2]).reshape(len(thetas), len(phis))
        # close the surface in phi
        r = np.concatenate([r, r[:, :1]], axis=1)
        th, ph = np.meshgrid(np.radians(thetas), np.radians(np.append(phis, 360.0)), indexing="ij")
        x, y, z = r * np.sin(th) * np.cos(ph), r * np.sin(th) * np.sin(ph), r * np.cos(th)
        ax.plot_surface(x, y, z, color=colours[i], alpha=0.45, linewidth=0.15, edgecolor=colours[i],
                        shade=True, antialiased=True)
    # the surface as a circle, the normal, and the incoming light
    ring = np.linspace(0, 2 * math.pi, 121)
    ax.plot(extent * np.cos(ring), extent * np.sin(ring), 0 * ring, color="0.4", lw=1)
    ax.plot([0, 0], [0, 0], [0, extent], color="0.4", lw=1, ls=":")
    ti, pi = math.radians(args.theta_in), math.radians(args.phi_in)
    wi = np.array([math.sin(ti) * math.cos(pi), math.sin(ti) * math.sin(pi), math.cos(ti)]) * extent
    ax.quiver(wi[0], wi[1], wi[2], -wi[0], -wi[1], -wi[2], color="black", lw=2, arrow_length_ratio=0.12)
    for i, lobes in enumerate(deltas):
        for r in lobes:
            t, p = math.radians(float(r["theta_deg"])), math.radians(float(r["phi_deg"]))
            d = np.array([math.sin(t) * math.cos(p), math.sin(t) * math.sin(p), math.cos(t)]) * extent * 0.9
            ax.quiver(0, 0, 0, d[0], d[1], d[2], color=colours[i], lw=2, ls="--", arrow_length_ratio=0.12)
    below = any(transmits)
    ax.set_xlim(-extent, extent)
    ax.set_ylim(-extent, extent)
    ax.set_zlim(-extent if below else 0, extent)
    ax.set_box_aspect((2, 2, 2 if below else 1), zoom=1.25 if below else 1.1)
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.pane.set_facecolor((0.97, 0.97, 0.97, 1.0))
        axis._axinfo["grid"]["color"] = (0.85, 0.85, 0.85, 1.0)
    ax.set_xlabel("x (tangent)")
    ax.set_ylabel("y")
    ax.set_zlabel("z (normal)")
    ax.tick_params(labelsize=7)
    if scale.log:
        for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
            axis.set_ticklabels([])
    ax.view_init(elev=22 if not below else 12, azim=args.phi_in - 65)
    ax.set_title("3D lobe: radius = luminance of f·|cos θo|" + (" (log)" if scale.log else ""), fontsize=11)


def legend_handles(names, deltas, colours):
    handles = [Line2D([], [], color=c, lw=2.5, label=n) for n, c in zip(names, colours)]
    for i, lobes in enumerate(deltas):
        for r in lobes:
            kind = "transmission" if r["transmission"] == "1" else "reflection"
            handles.append(Line2D([], [], color=colours[i], lw=2, ls="--", marker=">", markersize=6,
                                  label="%s: delta %s, weight %s (not a function)" % (names[i], kind, weight_text(r))))
    handles.append(Line2D([], [], color="black", lw=2, marker=">", markersize=6, label="incident light"))
    return handles


def main():
    parser = plot_common.argument_parser()
    parser.add_argument("--theta-in", type=float, required=True)
    parser.add_argument("--phi-in", type=float, required=True)
    parser.add_argument("--scale", choices=("auto", "linear", "log"), default="auto")
    args = parser.parse_args()

    names, transmits, plane, surface, deltas = load(args.data)
    colours = plot_common.material_colours(len(names))
    peaks = [max(v + [p[2] for p in s] + [0.0]) for (_, v), s in zip(plane, surface)]
    scale = RadialScale(peaks, args.scale)

    handles = legend_handles(names, deltas, colours)
    legend_in = 0.35 + 0.25 * math.ceil(len(handles) / 3)
    full = any(transmits)
    side = 0.43 * 16  # inches: the polar box is square
    plot_in = 6.4 if full else side / 2 + 1.5  # a half disc needs half the height
    fig = plt.figure(figsize=(16, plot_in + legend_in + 0.9))
    height = fig.get_figheight()
    bottom, top = legend_in / height, 1 - (1.15 if full else 0.9) / height
    if full:
        polar = fig.add_axes([0.04, bottom + 0.02, 0.43, top - bottom - 0.02], projection="polar")
    else:
        # the surface line (a quarter up the square box) just above the legend and the radial labels
        base = (legend_in + 0.5) / height
        polar = fig.add_axes([0.04, base - side / 4 / height, 0.43, side / height], projection="polar")
    draw_polar(polar, args, names, transmits, plane, deltas, colours, scale)
    view = fig.add_axes([0.5, bottom - 0.02, 0.48, top - bottom + 0.06], projection="3d")
    draw_3d(view, args, names, transmits, surface, deltas, colours, scale)
    fig.suptitle("BSDF lobes for light incident at θi = %g°, φi = %g°" % (args.theta_in, args.phi_in), fontsize=14, y=1 - 0.12 / height)
    fig.legend(handles=handles, loc="lower center", ncol=3, fontsize=9, frameon=False)
    plot_common.save(fig, args.out, dpi=110)


if __name__ == "__main__":
    main()
