#!/usr/bin/env python3
"""Throughput of dtoadq's path tracer against Mitsuba 3's, in the same run (docs/render.md, "Against
an independent renderer").

Mitsuba 3 intersects spheres and boxes analytically on the CPU. Its `scalar_rgb` variant needs no
LLVM: `pip install mitsuba` (into a virtual environment) is all. This script is a measurement tool,
not a test: the test run never calls it.

For each scene, both renderers render the same image (size, camera, lights, Lambert albedos, path
length) for about --seconds, alternating, --repeats times; the figure is paths (samples) per second,
the median over the repeats, and the ratio dtoadq / Mitsuba. dtoadq's come from the spp and seconds
its EXR records (as `dtoadq bench compare` reads them); Mitsuba's from the wall time of mi.render(),
after a warm-up render, on all the machine's threads (dtoadq's OpenCL device uses all of them too).
The image means are printed beside them: a converted scene that differed would show there.

Scenes: the one Lambert sphere under envmaps/courtyard.exr (tools/bench_scenes/sphere.json; both
renderers read the lat-long image with the same convention, docs/environments.md) and the Cornell box
(scenes/cornell_box.json). The converter knows only what these two use: translate, rotate about an
axis, box and sphere shapes, Lambert materials, sphere emitters.
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def load(path):
    with open(os.path.join(ROOT, path)) as f:
        return json.load(f)


def shape_to_mitsuba(mi, shape, material):
    """A dtoadq shape tree of translates and rotations over one box or sphere, as a Mitsuba shape."""
    T = mi.ScalarTransform4f
    to_world = T()
    while shape["type"] in ("translate", "rotate"):
        if shape["type"] == "translate":
            to_world = to_world @ T().translate(shape["offset"])
        else:
            to_world = to_world @ T().rotate(shape["axis"], shape["degrees"])
        shape = shape["child"]
    if shape["type"] == "box":
        return {"type": "cube", "to_world": to_world @ T().scale(shape["half_size"]), "bsdf": material}
    if shape["type"] == "sphere":
        return {"type": "sphere", "to_world": to_world @ T().scale(shape["radius"]), "bsdf": material}
    sys.exit(f"peer_mitsuba.py: shape type {shape['type']} is not converted")


def scene_to_mitsuba(mi, scene, env, size, max_depth, roulette_depth):
    camera = scene["camera"]
    T = mi.ScalarTransform4f
    d = {
        "type": "scene",
        # dtoadq's max depth counts scattering events; Mitsuba's counts the path's segments, the one
        # that reaches the light included
        "integrator": {"type": "path", "max_depth": max_depth + 1, "rr_depth": roulette_depth},
        "sensor": {
            "type": "perspective",
            "fov": camera["fov_degrees"],
            "fov_axis": "y",
            "to_world": T().look_at(origin=camera["position"], target=camera["look_at"], up=[0, 1, 0]),
            "sampler": {"type": "independent"},
            "film": {"type": "hdrfilm", "width": size, "height": size, "rfilter": {"type": "box"}, "pixel_format": "rgb"},
        },
    }
    materials = {}
    for name, m in scene["materials"].items():
        if set(m.get("lobes", {"diffuse": 1}).keys()) != {"diffuse"}:
            sys.exit(f"peer_mitsuba.py: material {name} is not Lambert")
        materials[name] = {"type": "diffuse", "reflectance": {"type": "rgb", "value": m["albedo"]}}
    for i, o in enumerate(scene["objects"]):
        d[f"object_{i}"] = shape_to_mitsuba(mi, o["shape"], materials[o["material"]])
    for i, e in enumerate(scene.get("emitters", [])):
        d[f"emitter_{i}"] = {
            "type": "sphere",
            "to_world": T().translate(e["center"]) @ T().scale(e["radius"]),
            "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": [0, 0, 0]}},
            "emitter": {"type": "area", "radiance": {"type": "rgb", "value": e["radiance"]}},
        }
    if env:
        d["environment"] = {"type": "envmap", "filename": os.path.join(ROOT, env)}
    return d


def mitsuba_paths_per_second(mi, scene, size, seconds, seed):
    spp = 4
    image = mi.render(scene, spp=spp, seed=seed)  # warm-up: loads and builds what the first render needs
    while True:
        start = time.perf_counter()
        image = mi.render(scene, spp=spp, seed=seed)
        elapsed = time.perf_counter() - start
        if elapsed >= seconds * 0.5:
            return size * size * spp / elapsed, float(np.mean(np.array(image)))
        spp = max(spp * 2, int(spp * seconds / max(elapsed, 1e-3)))


def exr_metadata(mi, path):
    """dtoadq's spp and render seconds from its EXR's header, and the image's mean."""
    bitmap = mi.Bitmap(path)
    header = bitmap.metadata()
    return int(header["dtoadq:spp"]), float(header["dtoadq:seconds"]), float(np.mean(np.array(bitmap)[:, :, :3]))


def dtoadq_paths_per_second(mi, dtoadq, scene_file, env, size, seconds, max_depth, folder):
    out = os.path.join(folder, "dtoadq.exr")
    command = [dtoadq, "render", scene_file, "--size", f"{size}x{size}", "--time", str(seconds), "--max-depth", str(max_depth), "--quiet",
               "-o", out]
    if env:
        command += ["--env", os.path.join(ROOT, env)]
    subprocess.run(command, check=True)
    spp, rendered, mean = exr_metadata(mi, out)
    return spp * size * size / rendered, mean


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--dtoadq", default=os.path.join(ROOT, "build", "cli", "dtoadq"))
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--seconds", type=float, default=5.0)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--max-depth", type=int, default=16)
    args = parser.parse_args()

    import mitsuba as mi

    mi.set_variant("scalar_rgb")
    # courtyard.exr holds a few tiny negative values, which Mitsuba warns about at every sample
    # that meets them (dtoadq clamps them to 0 when it converts the map)
    mi.set_log_level(mi.LogLevel.Error)
    roulette_depth = 3  # dtoadq's roulette_depth (docs/render.md); Mitsuba's rr_depth counts the same bounces
    cases = [("one sphere, courtyard.exr", "tools/bench_scenes/sphere.json", "envmaps/courtyard.exr"),
             ("Cornell box", "scenes/cornell_box.json", None)]
    print(f"{args.size}x{args.size}, max depth {args.max_depth}, {args.seconds} s per figure, median of {args.repeats}; "
          f"Mitsuba {mi.__version__} scalar_rgb")
    print(f"{'scene':28} {'dtoadq paths/s':>15} {'Mitsuba paths/s':>16} {'ratio':>7}   image means (dtoadq, Mitsuba)")
    with tempfile.TemporaryDirectory() as folder:
        for name, file, env in cases:
            scene = mi.load_dict(scene_to_mitsuba(mi, load(file), env, args.size, args.max_depth, roulette_depth))
            dtoadq_paths_per_second(mi, args.dtoadq, os.path.join(ROOT, file), env, args.size, 1.0, args.max_depth, folder)  # warm-up
            ours, theirs, ratios = [], [], []
            for r in range(args.repeats):
                o, mean_ours = dtoadq_paths_per_second(mi, args.dtoadq, os.path.join(ROOT, file), env, args.size, args.seconds, args.max_depth,
                                                       folder)
                t, mean_theirs = mitsuba_paths_per_second(mi, scene, args.size, args.seconds, r)
                ours.append(o)
                theirs.append(t)
                ratios.append(o / t)
            print(f"{name:28} {statistics.median(ours):15.3g} {statistics.median(theirs):16.3g} {statistics.median(ratios):6.2f}x"
                  f"   ({mean_ours:.4g}, {mean_theirs:.4g}); paired ratios {min(ratios):.2f}-{max(ratios):.2f}")


if __name__ == "__main__":
    main()
