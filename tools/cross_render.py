#!/usr/bin/env python3
"""Renders materials exported by `dtoadq convert` in Mitsuba 3 and compares them with the lab's own
render, region by region (docs/interchange.md, "Rendered by another renderer").

For each material (an openpbr preset; by default one of each class both models express: Lambert,
smooth and rough conductors, smooth and rough dielectrics, and the rough ones again without the
lab's multiple scattering, `energy_compensation` false), the script writes the preset, converts it to Mitsuba 3 XML with
`dtoadq convert` (printing its notes), and renders one sphere of radius 1 under
envmaps/courtyard.exr with the camera of tools/bench_scenes/sphere.json in both renderers:
`dtoadq render` (the path tracer, OpenCL device or --device) and Mitsuba's `path` integrator in the
`scalar_rgb` variant, each in --batches independent renders (other seeds). Both read the lat-long
image with the same convention (docs/render.md, "Against an independent renderer").

Only pixels whose whole footprint lies on the sphere are compared; the sphere's bounding square is
cut into --grid x --grid regions. Per region and channel it prints the relative difference
(lab - Mitsuba) / Mitsuba of the means over all batches and its z, the difference over its standard
error from the batches' spread; per material the largest |relative difference| and |z|. A class
both models express agrees within noise where |z| stays within the normal quantile of the
comparison's family-wise level (Sidak over every region and channel of all materials).

A measurement tool, not a test: `pip install mitsuba` (a large wheel) into a virtual environment.
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

CLASSES = {
    "lambert": {"base_color": [0.7, 0.5, 0.3], "specular_weight": 0.0},
    "smooth_conductor": {"base_color": [0.95, 0.64, 0.54], "base_metalness": 1.0, "specular_roughness": 0.0},
    "rough_conductor": {"base_color": [0.95, 0.64, 0.54], "base_metalness": 1.0, "specular_roughness": 0.5},
    "rough_conductor_single_scattering": {"base_color": [0.95, 0.64, 0.54], "base_metalness": 1.0, "specular_roughness": 0.5,
                                          "energy_compensation": False},
    "smooth_dielectric": {"transmission_weight": 1.0, "specular_roughness": 0.0, "specular_ior": 1.5},
    "rough_dielectric": {"transmission_weight": 1.0, "specular_roughness": 0.3, "specular_ior": 1.5},
    "rough_dielectric_single_scattering": {"transmission_weight": 1.0, "specular_roughness": 0.3, "specular_ior": 1.5,
                                           "energy_compensation": False},
}


def normal_quantile(p):
    """The standard normal quantile by bisection on erf (no scipy needed)."""
    lo, hi = -40.0, 40.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if 0.5 * (1.0 + math.erf(mid / math.sqrt(2.0))) < p:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def sphere_mask(size, camera):
    """Pixels whose four corners' rays all hit the unit sphere at the origin (pinhole camera on +z)."""
    distance = np.linalg.norm(np.array(camera["position"]) - np.array(camera["look_at"]))
    tan_half = math.tan(math.radians(camera["fov_degrees"]) / 2.0)
    corners = (np.arange(size + 1) / size * 2.0 - 1.0) * tan_half
    x, y = np.meshgrid(corners, -corners)
    # a ray from (0, 0, d) along (x, y, -1) misses the sphere where its distance to the centre exceeds 1
    hit = (distance * distance * (x * x + y * y)) / (1.0 + x * x + y * y) <= 1.0
    return hit[:-1, :-1] & hit[1:, :-1] & hit[:-1, 1:] & hit[1:, 1:]


def regions(mask, grid):
    rows, cols = np.nonzero(mask)
    r0, r1, c0, c1 = rows.min(), rows.max() + 1, cols.min(), cols.max() + 1
    out = []
    for i in range(grid):
        for j in range(grid):
            region = np.zeros_like(mask)
            region[r0 + (r1 - r0) * i // grid:r0 + (r1 - r0) * (i + 1) // grid, c0 + (c1 - c0) * j // grid:c0 + (c1 - c0) * (j + 1) // grid] = True
            region &= mask
            if region.sum() >= 8:
                out.append(region)
    return out


def lab_batches(args, preset_path, camera, folder, mi):
    scene = {"camera": camera, "materials": {"m": preset_path}, "objects": [{"name": "sphere", "material": "m", "shape": {"type": "sphere", "radius": 1.0}}]}
    scene_path = os.path.join(folder, "scene.json")
    with open(scene_path, "w") as f:
        json.dump(scene, f)
    images = []
    for b in range(args.batches):
        out = os.path.join(folder, f"lab{b}.exr")
        command = [args.dtoadq, "render", scene_path, "--env", os.path.join(ROOT, args.env), "--size", f"{args.size}x{args.size}",
                   "--spp", str(args.spp), "--seed", str(b + 1), "--max-depth", str(args.max_depth), "--quiet", "-o", out]
        if args.device:
            command += ["--device", args.device]
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        images.append(np.array(mi.Bitmap(out))[:, :, :3].astype(np.float64))
    return images


def mitsuba_batches(args, xml_path, bsdf_id, camera, mi):
    scene_xml = f"""<scene version="3.0.0">
  <include filename="{xml_path}"/>
  <integrator type="path"><integer name="max_depth" value="{args.max_depth + 1}"/><integer name="rr_depth" value="3"/></integrator>
  <sensor type="perspective">
    <float name="fov" value="{camera['fov_degrees']}"/><string name="fov_axis" value="y"/>
    <transform name="to_world"><lookat origin="{','.join(map(str, camera['position']))}" target="{','.join(map(str, camera['look_at']))}" up="0,1,0"/></transform>
    <sampler type="independent"/>
    <film type="hdrfilm"><integer name="width" value="{args.size}"/><integer name="height" value="{args.size}"/>
      <rfilter type="box"/><string name="pixel_format" value="rgb"/></film>
  </sensor>
  <emitter type="envmap"><string name="filename" value="{os.path.join(ROOT, args.env)}"/></emitter>
  <shape type="sphere"><ref id="{bsdf_id}"/></shape>
</scene>
"""
    path = os.path.join(os.path.dirname(xml_path), "mitsuba_scene.xml")
    with open(path, "w") as f:
        f.write(scene_xml)
    scene = mi.load_file(path)
    return [np.array(mi.render(scene, spp=args.spp, seed=b + 1)).astype(np.float64)[:, :, :3] for b in range(args.batches)]


def region_stats(images, region):
    """Per channel: the mean over batches of the region's mean, and its standard error."""
    means = np.array([[image[:, :, c][region].mean() for c in range(3)] for image in images])
    return means.mean(axis=0), means.std(axis=0, ddof=1) / math.sqrt(len(images))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--dtoadq", default=os.path.join(ROOT, "build", "cli", "dtoadq"))
    parser.add_argument("--device", default="", help="dtoadq's --device (default: its own choice)")
    parser.add_argument("--env", default="envmaps/courtyard.exr")
    parser.add_argument("--size", type=int, default=64)
    parser.add_argument("--spp", type=int, default=256, help="samples per pixel of each batch, in both renderers")
    parser.add_argument("--batches", type=int, default=8)
    parser.add_argument("--grid", type=int, default=3)
    parser.add_argument("--max-depth", type=int, default=16)
    parser.add_argument("--level", type=float, default=0.01, help="family-wise level of the within-noise verdicts")
    parser.add_argument("classes", nargs="*", default=list(CLASSES), help=f"material classes: {', '.join(CLASSES)}")
    args = parser.parse_args()

    import mitsuba as mi

    mi.set_variant("scalar_rgb")
    mi.set_log_level(mi.LogLevel.Error)  # courtyard.exr's few tiny negative texels warn at every sample that meets them
    with open(os.path.join(ROOT, "tools", "bench_scenes", "sphere.json")) as f:
        camera = json.load(f)["camera"]
    mask = sphere_mask(args.size, camera)
    cells = regions(mask, args.grid)
    tests = len(cells) * 3 * len(args.classes)
    z_bound = normal_quantile(1.0 - (1.0 - (1.0 - args.level) ** (1.0 / tests)) / 2.0)
    print(f"{args.size}x{args.size}, {len(cells)} regions on the sphere, {args.batches} batches of {args.spp} spp per renderer, "
          f"max depth {args.max_depth}; Mitsuba {mi.__version__} scalar_rgb; |z| bound {z_bound:.2f} "
          f"(family-wise level {args.level} over {tests} region-channels)")
    summary = []
    for name in args.classes:
        with tempfile.TemporaryDirectory() as folder:
            preset = dict({"name": name, "model": "openpbr"}, **CLASSES[name])
            preset_path = os.path.join(folder, f"{name}.json")
            with open(preset_path, "w") as f:
                json.dump(preset, f)
            xml_path = os.path.join(folder, f"{name}.xml")
            converted = subprocess.run([args.dtoadq, "convert", preset_path, "-o", xml_path, "--quiet"], check=True, capture_output=True, text=True)
            notes = [line for line in converted.stderr.splitlines() if line]
            lab = lab_batches(args, preset_path, camera, folder, mi)
            theirs = mitsuba_batches(args, xml_path, name, camera, mi)
        print(f"\n{name}: {json.dumps(CLASSES[name])}")
        for note in notes:
            print("  " + note)
        print(f"  {'region':>6} {'lab (R G B)':>26} {'Mitsuba (R G B)':>26} {'relative difference, %':>26} {'z':>20}")
        worst_rel, worst_z = 0.0, 0.0
        for k, cell in enumerate(cells):
            m1, s1 = region_stats(lab, cell)
            m2, s2 = region_stats(theirs, cell)
            rel = (m1 - m2) / np.maximum(m2, 1e-12)
            z = (m1 - m2) / np.maximum(np.sqrt(s1 * s1 + s2 * s2), 1e-12)
            worst_rel, worst_z = max(worst_rel, float(np.abs(rel).max())), max(worst_z, float(np.abs(z).max()))
            fmt = lambda v, w: " ".join(f"{x:{w}}" for x in v)
            print(f"  {k:>6} {fmt(m1, '8.4f'):>26} {fmt(m2, '8.4f'):>26} {fmt(rel * 100, '+7.2f'):>26} {fmt(z, '+6.1f'):>20}")
        verdict = "within noise" if worst_z <= z_bound else "differs"
        print(f"  largest |relative difference| {worst_rel * 100:.2f} %, largest |z| {worst_z:.1f}: {verdict}")
        summary.append((name, worst_rel, worst_z, verdict))
    print("\nclass                               largest |rel. diff.|  largest |z|")
    for name, rel, z, verdict in summary:
        print(f"{name:35} {rel * 100:18.2f} % {z:12.1f}  {verdict}")


if __name__ == "__main__":
    sys.exit(main())
