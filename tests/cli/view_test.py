#!/usr/bin/env python3
"""End-to-end test of `dtoadq view` under a display (Xvfb with Mesa's software OpenGL when there is
no DISPLAY): the window opens and samples accumulate, the screenshot shows the model on the backdrop,
a scripted --set changes the model and not the backdrop, a saved preset loads back identical,
--export-to writes a scene that `dtoadq render` renders with the material, the rest unchanged, and a
map loaded in the window replaces the environment, or, when missing, leaves it and shows the error;
the look-dev references come and go, the backdrop's opacity and the shadow catcher follow the
environment panel's script, a resize changes the render area and the render, every panel section
opens without overlap, the denoised display is nearer a longer render than the raw one, a change
never waits for the denoiser's filter, and every
view of the view menu shows what it should.

usage: view_test.py DTOADQ SCRATCH_DIR [CASE]   (CASE: one of CASES; default all). Exit 77: skipped.
"""
import json
import os
import re
import shutil
import subprocess
import sys

SKIP = 77
EXE, SCRATCH = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
SIZE = 64  # the render is the window's top-left SIZE x SIZE pixels
# The model fills the centre of the test model's view; the top corners see only the environment
# (with --ground off nothing else is there).
CENTRE = (slice(20, 44), slice(20, 44))
CORNERS = [(slice(0, 6), slice(0, 6)), (slice(0, 6), slice(SIZE - 6, SIZE))]
SKY = (0.2, 0.4, 1.0)
ENV = "constant:%g,%g,%g" % SKY
RED = "0.6,0.04,0.03"      # the test model's own albedo (scenes/shader_ball.json)
GREEN = "0.05,0.9,0.05"


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run(args, expect_ok=True):
    p = subprocess.run([EXE] + args, cwd=SCRATCH, capture_output=True, text=True, timeout=180)
    if expect_ok and p.returncode != 0:
        fail("dtoadq %s exited %d: %s" % (" ".join(args), p.returncode, p.stderr.strip()))
    return p


def view(extra, shot, frames=4, min_spp=2, size=SIZE, scene=("--env", ENV, "--ground", "off"), device="host"):
    args = ["view", "--size", "%dx%d" % (size, size), "--device", device] + list(scene) + [
            "--frames", str(frames), "--min-spp", str(min_spp), "--screenshot", shot] + extra
    return run(args).stdout


def displayed(linear):
    """A backdrop pixel's PNG code in closed form: ACES (Narkowicz 2015) then the sRGB curve."""
    x = linear * (2.51 * linear + 0.03) / (linear * (2.43 * linear + 0.59) + 0.14)
    x = min(max(x, 0.0), 1.0)
    encoded = 12.92 * x if x <= 0.0031308 else 1.055 * x ** (1.0 / 2.4) - 0.055
    return round(encoded * 255.0)


def read_png(path):
    import matplotlib.image
    return matplotlib.image.imread(os.path.join(SCRATCH, path))[:, :, :3] * 255.0  # PNG codes


def mean(image, region):
    return image[region[0], region[1]].reshape(-1, 3).mean(axis=0)


def case_accumulate():
    out = view(["--seed", "1", "--inspect", "32,32", "--inspect", "2,2"], "a.png")
    # The pixel inspector: the centre pixel's ray meets the model's slot, a corner's none.
    if not re.search(r"inspect: pixel 32,32; radiance .*; depth [0-9.]+; normal .*; material slot 0 \(sample\)", out):
        fail("the inspector did not find the model at the centre: " + out)
    if not re.search(r"inspect: pixel 2,2; radiance 0.2 0.4 1 .*; no surface: the environment", out):
        fail("the inspector did not find the environment in the corner: " + out)
    m = re.search(r"view: (\d+) frames, (\d+) spp", out)
    if not m or int(m.group(2)) < 2:
        fail("no samples accumulated: " + out)
    a = read_png("a.png")
    if a[:SIZE, :SIZE].std() < 5.0:
        fail("the render area is blank (std %.2f codes)" % a[:SIZE, :SIZE].std())
    backdrop = mean(a, CORNERS[0])
    centre = mean(a, CENTRE)
    expected = [displayed(c) for c in SKY]
    if abs(backdrop - expected).max() > 1.0:
        fail("the backdrop is %s, not the environment's %s" % (backdrop, expected))
    # The model's red albedo under a blue sky: red stands above blue in the centre.
    if not centre[0] - centre[2] > 20.0:
        fail("no model in the centre: centre %s, backdrop %s" % (centre, backdrop))
    print("accumulate: %s; centre %s backdrop %s" % (m.group(0), centre.round(1), backdrop.round(1)))


def case_set():
    view(["--seed", "1"], "a.png")
    view(["--seed", "2"], "a2.png")  # the same material with other random numbers: the noise figure
    view(["--seed", "1", "--set", "albedo=%s@2" % GREEN], "b.png")
    a, a2, b = read_png("a.png"), read_png("a2.png"), read_png("b.png")
    noise = abs(mean(a, CENTRE) - mean(a2, CENTRE)).max()
    change = abs(mean(a, CENTRE) - mean(b, CENTRE)).max()
    if not change > 3.0 * noise + 2.0:
        fail("the --set did not change the model: %.2f codes against a seed-to-seed noise of %.2f" % (change, noise))
    for corner in CORNERS:  # the environment seen directly: no material in it, so exactly the same
        if abs(a[corner[0], corner[1]] - b[corner[0], corner[1]]).max() > 1.0:
            fail("the --set changed the backdrop")
    print("set: model changed by %.1f codes (noise %.1f); backdrop unchanged" % (change, noise))


def case_preset():
    run(["view", "--size", "16x16", "--device", "host", "--env", ENV, "--frames", "1", "--set", "albedo=%s@0" % GREEN,
         "--set", "roughness=0.37@0", "--set", "tangent_rotation=33@0", "--save-preset", "p.json"])
    run(["view", "--size", "16x16", "--device", "host", "--env", ENV, "--frames", "1", "--material", "p.json", "--save-preset", "p2.json"])
    first, second = open(os.path.join(SCRATCH, "p.json")).read(), open(os.path.join(SCRATCH, "p2.json")).read()
    if first != second:
        fail("the saved preset did not load back identical:\n%s\n%s" % (first, second))
    saved = json.loads(first)
    if abs(saved["roughness"] - 0.37) > 1e-6 or abs(saved["albedo"][1] - 0.9) > 1e-6:
        fail("the saved preset lacks the scripted values: %s" % first)
    print("preset: loads back identical")


def case_export():
    source = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenes", "shader_ball.json")
    shutil.copy(source, os.path.join(SCRATCH, "ball.json"))
    original = json.load(open(os.path.join(SCRATCH, "ball.json")))
    run(["view", "--size", "16x16", "--device", "host", "--env", ENV, "--frames", "1", "--set", "albedo=%s@0" % GREEN,
         "--export-to", "ball.json:sample"])
    exported = json.load(open(os.path.join(SCRATCH, "ball.json")))
    if abs(exported["materials"]["sample"]["albedo"][1] - 0.9) > 1e-6:
        fail("the exported material is not the viewer's: %s" % exported["materials"]["sample"])
    for doc in (original, exported):
        del doc["materials"]["sample"]
    if original != exported:
        fail("export changed the rest of the scene file")
    run(["render", "ball.json", "--env", ENV, "--device", "host", "--size", "%dx%d" % (SIZE, SIZE), "--spp", "2", "--quiet",
         "-o", "ball.png"])
    centre = mean(read_png("ball.png"), CENTRE)
    if not centre[1] - centre[0] > 20.0:  # the model renders green, not the scene's red
        fail("dtoadq render did not use the exported material: centre %s" % centre)
    print("export: rest of the scene unchanged; render centre %s" % centre.round(1))


def case_env():
    source = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    base = ["--inspect", "2,2", "--load-env"]
    # A missing map: its one-line error in the window, the old environment still rendered.
    out = view(base + ["absent.exr@1"], "badmap.png")
    if "view: message: absent.exr: no such file" not in out:
        fail("no error for a missing map: " + out)
    if not re.search(r"inspect: pixel 2,2; radiance 0.2 0.4 1 ", out):
        fail("a missing map did not keep the last good environment: " + out)
    # A real map replaces the constant one.
    out = view(base + [os.path.join(source, "envmaps", "studio.exr") + "@1"], "goodmap.png")
    if "message" in out or re.search(r"inspect: pixel 2,2; radiance 0.2 0.4 1 ", out) or "no surface: the environment" not in out:
        fail("the map was not loaded: " + out)
    print("env: a missing map keeps the old one and says why; a good one replaces it")


def case_references():
    """The look-dev references switched on and off in the window: the grey ball's pixel (at 0.73, 0.86
    of the view: scene/look_dev_references.hpp) shows it, then the sky again."""
    out = view(["--load-references", "grey@1", "--inspect", "46,55"], "refs_on.png")
    if not re.search(r"inspect: pixel 46,55; radiance .*; material slot \d+ \(reference_grey\)", out):
        fail("the grey ball did not appear: " + out)
    out = view(["--references", "all", "--load-references", "none@1", "--inspect", "46,55"], "refs_off.png")
    if not re.search(r"inspect: pixel 46,55; radiance 0.2 0.4 1 .*; no surface: the environment", out):
        fail("the references did not go: " + out)
    print("references: the grey ball comes and goes")


def case_background():
    """The environment panel's backdrop controls: opacity 0 at a frame blackens the sky's pixels (the
    model keeps its light), and the shadow catcher ticked on takes the ground's place under the model,
    its pixel the sky's radiance (nothing shadows the inspected pixel enough to tell at 2 spp)."""
    out = view(["--move", "background_opacity=0@1", "--inspect", "2,2"], "bg_hidden.png")
    if not re.search(r"inspect: pixel 2,2; radiance 0 0 0 .*; no surface: the environment", out):
        fail("opacity 0 left the sky: " + out)
    image = read_png("bg_hidden.png")
    for rows, cols in CORNERS:
        if image[rows, cols].max() > 0:
            fail("a corner of the screenshot is not black at opacity 0")
    if image[CENTRE].max() < 20:
        fail("the model went dark with the backdrop")
    out = view(["--load-references", "catcher@1", "--inspect", "32,62"], "catcher.png")
    if not re.search(r"inspect: pixel 32,62; radiance .*; material slot \d+ \(shadow_catcher\)", out):
        fail("the shadow catcher did not appear: " + out)
    print("background: opacity 0 hides the sky, the shadow catcher comes under the model")


REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def rms(a, b, region):
    return float((((a[region[0], region[1]] - b[region[0], region[1]]) ** 2).mean()) ** 0.5)


def case_denoise():
    """The display denoised (the default) against the raw mean of as many samples or more, on the
    case the filter is built for (a matte model on its ground under a real map, 96 x 96): on the
    model its error against a longer render (32 spp) falls to under 0.7 of the raw's. The longer
    render's own error is about a quarter of the 2-spp image's: it lowers neither error by more
    than 4 %. (That the filter leaves the background and the film alone is tested on the renders.)
    The longer render is the same path tracer on the OpenCL device: on the host build its 300 000
    paths took 48 s of CPU, the most of any test; on the device 12 s with its kernels' cold build."""
    scene = ("--env", os.path.join(REPO, "envmaps", "courtyard.exr"), "--material", os.path.join(REPO, "presets", "clay.json"))
    model = (slice(30, 66), slice(30, 66))
    view(["--seed", "1"], "on.png", size=96, scene=scene)
    view(["--seed", "1", "--denoise", "off"], "off.png", size=96, scene=scene)
    view(["--seed", "2", "--denoise", "off"], "reference.png", frames=4, min_spp=32, size=96, scene=scene, device="cpu")
    a, b, ref = read_png("on.png"), read_png("off.png"), read_png("reference.png")
    error_on, error_off = rms(a, ref, model), rms(b, ref, model)
    if not error_on < 0.7 * error_off:
        fail("denoising did not bring the model nearer the longer render: RMS %.2f codes denoised against %.2f raw" % (error_on, error_off))
    print("denoise: RMS against 32 spp %.2f codes denoised, %.2f raw (%.2fx)" % (error_on, error_off, error_on / error_off))


def case_denoise_wait():
    """A change never waits for the display denoiser: with its filter stalled at its first image
    (DTOADQ_DEBUG_STALL_DENOISER=1: it does not return until the viewer closes), every scripted
    change still shows and samples still accumulate. A worker that waited for a running filter, or
    for its cancellation, would never show the first change after the stall, and the headless run,
    which ends only once every --set is shown, would not end."""
    env = dict(os.environ, DTOADQ_DEBUG_STALL_DENOISER="1")
    args = ["view", "--size", "%dx%d" % (SIZE, SIZE), "--device", "host", "--env", ENV, "--ground", "off", "--frames", "40",
            "--min-spp", "2"] + sum((["--set", "roughness=%g@%d" % (0.2 * i, 10 * i)] for i in (1, 2, 3)), [])
    try:
        p = subprocess.run([EXE] + args, cwd=SCRATCH, capture_output=True, text=True, timeout=30, env=env)
    except subprocess.TimeoutExpired:
        fail("the viewer did not show every change within 30 s while the denoiser's filter was stalled")
    if p.returncode != 0:
        fail("dtoadq %s exited %d: %s" % (" ".join(args), p.returncode, p.stderr.strip()))
    if "display denoiser: stalled" not in p.stderr:
        fail("the denoiser's filter never ran, so nothing waited on it: " + p.stderr)
    m = re.search(r"view: (\d+) frames, (\d+) spp", p.stdout)
    if not m or int(m.group(2)) < 2:
        fail("samples did not accumulate beside the stalled filter: " + p.stdout)


LAYOUT = re.compile(r"layout: window (\d+)x(\d+), render area (\d+)x(\d+), image (\d+),(\d+) (\d+)x(\d+), render (\d+)x(\d+), "
                    r"panel (\d+),(\d+) (\d+)x(\d+), columns (\d)")
SECTION = re.compile(r"section (\w+): (-?\d+),(-?\d+) (\d+)x(\d+)")


def layouts(out):
    return [tuple(int(g) for g in m.groups()) for m in LAYOUT.finditer(out)]


def case_resize():
    """A resize changes the render area, and the render follows it at its aspect."""
    out = view(["--seed", "1", "--window", "600x300", "--resize", "700x400@3", "--print-layout"], "resized.png")
    found = layouts(out)
    if len(found) != 2:
        fail("expected the first layout and the resized one: " + out)
    (w0, h0, aw0, ah0, _, _, iw0, ih0, rw0, rh0, *_), (w1, h1, aw1, ah1, ix1, iy1, iw1, ih1, rw1, rh1, px1, _, pw1, ph1, _) = found
    if (w0, h0, w1, h1) != (600, 300, 700, 400):
        fail("the window sizes are not the ones asked for: " + str(found))
    # The panel keeps its width; the render area takes what the window gained, the render follows it.
    if (aw1 - aw0, ah1 - ah0) != (100, 100) or (rw0, rh0) != (iw0, ih0) or (rw1, rh1) != (iw1, ih1) or rw1 != rh1 or rw1 <= rw0:
        fail("the render area and render did not follow the window: " + str(found))
    if px1 != aw1 or pw1 + aw1 != 700 or ph1 != 400:
        fail("the panel is not right of the render area: " + str(found))
    shot = read_png("resized.png")
    if shot.shape[:2] != (400, 700):
        fail("the screenshot is %s, not the resized window" % (shot.shape[:2],))
    # The render fills its square at the top left of the area; below it the window's background.
    image = shot[iy1:iy1 + ih1, ix1:ix1 + iw1]
    if image.std() < 5.0 or abs(mean(shot, CORNERS[0]) - [displayed(c) for c in SKY]).max() > 1.0:
        fail("the render is not drawn in its new place: std %.1f, corner %s" % (image.std(), mean(shot, CORNERS[0])))
    print("resize: render area %dx%d -> %dx%d, render %dx%d -> %dx%d" % (aw0, ah0, aw1, ah1, rw0, rh0, rw1, rh1))


def case_sections():
    """Every section open at once on a 1920 x 1080 screen: two panel columns, no section over another
    or outside the panel, and material, checks and lobe wholly in view."""
    out = view(["--window", "1920x1080", "--open", "all", "--display", "scale", "--print-layout"], "sections.png")
    found = layouts(out)
    if not found or found[-1][14] != 2:
        fail("no two-column layout at 1920x1080: " + out)
    panel = found[-1][10:14]
    rects = {m.group(1): tuple(int(g) for g in m.groups()[1:]) for m in SECTION.finditer(out)}
    names = ["Material", "Checks", "Lobe", "Environment", "Presets", "Inspector", "Help"]
    if sorted(rects) != sorted(names):
        fail("not every section is open: " + str(sorted(rects)))
    for name, (x, y, w, h) in rects.items():
        if w < 100 or h < 60 or x < panel[0] or x + w > panel[0] + panel[2] or y < 0:
            fail("section %s at %s is not inside the panel %s" % (name, rects[name], panel))
    for a in names:
        for b in names:
            ra, rb = rects[a], rects[b]
            if a < b and ra[0] < rb[0] + rb[2] and rb[0] < ra[0] + ra[2] and ra[1] < rb[1] + rb[3] and rb[1] < ra[1] + ra[3]:
                fail("sections %s %s and %s %s overlap" % (a, ra, b, rb))
    for name in ("Material", "Checks", "Lobe"):
        if rects[name][1] + rects[name][3] > 1080:
            fail("section %s %s is not wholly in view" % (name, rects[name]))
    print("sections: %s" % rects)


def case_views():
    """Every view of the menu (--view-mode) shows what it should where the model and the sky are:
    the first-hit views black on the sky, the slot view the model's slot colour, samples the spp,
    the sky's false colour its band (luminance 0.40: 1.15 stops above 18 % grey), its variance
    none (every sample is the sky), the relative-error view marking the model at 2 spp and not the
    sky, the gamut view marking the sky once the exposure takes its blue above 1; --save-exr writes
    the chosen layers."""
    def shot(mode, extra=()):
        name = "view_%s.png" % mode
        view(["--seed", "1", "--view-mode", "%s@1" % mode] + list(extra), name)
        return read_png(name)[:SIZE, :SIZE]
    if shot("image").std() < 5.0:
        fail("the image view is blank")
    for mode in ("albedo", "normal", "depth", "slot"):
        v = shot(mode)
        if abs(mean(v, CORNERS[0])).max() > 0.5 or abs(mean(v, CORNERS[1])).max() > 0.5:
            fail("the %s view is not black on the sky: %s" % (mode, mean(v, CORNERS[0])))
        if mean(v, CENTRE).sum() < 60.0:
            fail("the %s view is black on the model: %s" % (mode, mean(v, CENTRE)))
        if mode == "albedo" and not mean(v, CENTRE)[0] > mean(v, CENTRE)[1] + 20.0:
            fail("the albedo view of the red model is not red: %s" % mean(v, CENTRE))
        if mode == "depth" and abs(v[32, 32, 0] - v[32, 32, 2]) > 0.5:
            fail("the depth view is not grey: %s" % v[32, 32])
        if mode == "slot" and abs(v[32, 32] - (230, 159, 0)).max() > 0.5:  # slot 0's colour
            fail("the slot view does not show slot 0 at the centre: %s" % v[32, 32])
    # Every pixel holds the complete passes' n samples, and those the pass in progress has reached
    # (the first pixels in row order) one more: white, then n / (n + 1) grey after them.
    codes = shot("samples")[:, :, 0].reshape(-1).round()
    levels = sorted(set(codes))
    lower = codes < 255
    if levels[-1] != 255 or len(levels) > 2 or (lower.any() and not lower[lower.argmax():].all()) or levels[0] < 127:
        fail("the samples view is not white up to where the pass in progress has reached: levels %s" % levels)
    v = shot("variance")
    if mean(v, CORNERS[0]).max() > 8.0 or not mean(v, CENTRE).mean() > mean(v, CORNERS[0]).mean() + 20.0:
        fail("the variance view: sky %s, model %s" % (mean(v, CORNERS[0]), mean(v, CENTRE)))
    v = shot("false-colour")
    if abs(mean(v, CORNERS[0]) - (230, 220, 60)).max() > 0.5:  # the band from +1 to +2 stops
        fail("the false-colour view of the sky is %s, not the +1 band's colour" % mean(v, CORNERS[0]))
    v = shot("relative-error", ["--error-threshold", "0.05"])
    red = ((v[:, :, 0] > 250) & (v[:, :, 1] < 5) & (v[:, :, 2] < 5))
    if red[CENTRE].mean() < 0.5 or red[CORNERS[0]].any() or red[CORNERS[1]].any():
        fail("the relative-error view marks %.2f of the model and %d sky pixels" % (red[CENTRE].mean(), red[CORNERS[0]].sum()))
    v = shot("gamut")
    if red_share(v, CORNERS[0]) > 0.0 or abs(v[2, 2, 0] - v[2, 2, 2]) > 0.5:
        fail("the gamut view marks the sky at exposure 0: %s" % v[2, 2])
    v = shot("gamut", ["--exposure", "1"])
    if red_share(v, CORNERS[0]) < 1.0:
        fail("the gamut view does not mark the sky whose blue is 2 after the exposure: %s" % v[2, 2])
    # --save-exr: the frame with the chosen layers, named as render --aov names them
    out = view(["--seed", "1", "--save-exr", "views.exr", "--save-layers", "albedo,depth,slot,variance,samples"], "save.png")
    if "wrote views.exr" not in out:
        fail("--save-exr wrote nothing: " + out)
    info = subprocess.run(["oiiotool", "--info", "-v", "views.exr"], cwd=SCRATCH, capture_output=True, text=True).stdout
    channels = re.search(r"channel list: (.*)", info)
    expected = "R, G, B, IndexMA.X, albedo.R, albedo.G, albedo.B, depth.Z, samples.X, variance.R, variance.G, variance.B"
    if not channels or channels.group(1).strip() != expected:
        fail("views.exr's channels: %s, expected %s" % (channels.group(1) if channels else info, expected))
    stats = subprocess.run(["oiiotool", "views.exr", "--ch", "samples.X", "--printstats"], cwd=SCRATCH, capture_output=True,
                           text=True).stdout
    low = re.search(r"Stats Min: ([0-9.]+)", stats)
    if not low or float(low.group(1)) < 2.0:
        fail("views.exr's samples.X is under the 2 spp the run waited for: " + stats)


def red_share(image, region):
    r = image[region[0], region[1]]
    return ((r[:, :, 0] > 250) & (r[:, :, 1] < 5) & (r[:, :, 2] < 5)).mean()


CASES = {"accumulate": case_accumulate, "set": case_set, "preset": case_preset, "export": case_export, "env": case_env,
         "references": case_references, "background": case_background, "resize": case_resize, "sections": case_sections,
         "denoise": case_denoise, "denoise_wait": case_denoise_wait, "views": case_views}

if __name__ == "__main__":
    if not os.environ.get("DISPLAY"):
        if not shutil.which("xvfb-run"):
            print("SKIP: no DISPLAY and no xvfb-run (install xvfb: tools/install-deps.sh)")
            sys.exit(SKIP)
        # -a: a free display number, so parallel tests do not collide
        sys.exit(subprocess.call(["xvfb-run", "-a", "-s", "-screen 0 1920x1080x24", sys.executable] + sys.argv))
    os.makedirs(SCRATCH, exist_ok=True)
    for name in (sys.argv[3:] or CASES):
        CASES[name]()
