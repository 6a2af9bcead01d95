#!/usr/bin/env python3
"""End-to-end test of `dtoadq view --turntable` (headless, on the host renderer): in `model` mode the
background stays put while the model turns (the camera and the map turn together about the model's
axis, so the world's turn is the model's); in `environment` mode the background turns and the model
stays; a video has one frame per rendered frame.

usage: turntable_test.py DTOADQ ENVMAP SCRATCH_DIR CASE   (CASE: model, environment, video). Exit 77: skipped.
"""
import os
import shutil
import subprocess
import sys

SKIP = 77
EXE, ENVMAP, SCRATCH = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), os.path.abspath(sys.argv[3])
SIZE, FRAMES = 48, 4


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def turntable(extra, output, seed=0):
    args = [EXE, "view", "--turntable", str(FRAMES), "--spp", "4", "--size", "%dx%d" % (SIZE, SIZE), "--device", "host",
            "--env", ENVMAP, "--ground", "off", "--quiet", "--seed", str(seed), "-o", output] + extra
    p = subprocess.run(args, cwd=SCRATCH, capture_output=True, text=True, timeout=300)
    if p.returncode != 0:
        fail("%s exited %d: %s" % (" ".join(args), p.returncode, p.stderr.strip()))
    return p.stdout


def frames(prefix):
    import matplotlib.image
    return [matplotlib.image.imread(os.path.join(SCRATCH, "%s_%02d.png" % (prefix, k)))[:, :, :3] * 255.0 for k in range(FRAMES)]


def differences(a, b):
    """How much b differs from a in PNG codes: the largest mean absolute difference of a channel over
    the top rows (only the sky there), and the largest difference of a channel's mean over the
    model's box in the middle (the pixels' own noise averages out there)."""
    top, middle = slice(0, 6), slice(SIZE // 4, 3 * SIZE // 4)
    sky = abs(a[top] - b[top]).mean()
    model = abs(a[middle, middle].reshape(-1, 3).mean(axis=0) - b[middle, middle].reshape(-1, 3).mean(axis=0)).max()
    return sky, model


def case_model():
    turntable([], "m_%02d.png")
    turntable([], "n_%02d.png", seed=7)
    m, n = frames("m"), frames("n")
    _, noise = differences(m[0], n[0])  # the same frame with other random numbers
    for k in range(1, FRAMES):
        sky, model = differences(m[0], m[k])
        if sky > 0.5:
            fail("frame %d: the background moved by %.2f codes: the map did not turn with the camera" % (k, sky))
    _, half_turn = differences(m[0], m[FRAMES // 2])
    if not half_turn > 3.0 * noise + 1.0:
        fail("the model did not turn: half a turn changes it by %.2f codes against %.2f of noise" % (half_turn, noise))
    print("model: background still, half a turn changes the model by %.1f codes (noise %.1f)" % (half_turn, noise))


def case_environment():
    turntable(["--turn", "environment"], "e_%02d.png")
    e = frames("e")
    sky, _ = differences(e[0], e[1])
    if not sky > 5.0:
        fail("the environment did not turn: the background changed by %.2f codes" % sky)
    print("environment: the background turns (%.1f codes at a quarter turn)" % sky)


def case_video():
    if not shutil.which("ffmpeg") or not shutil.which("ffprobe"):
        print("SKIP: no ffmpeg (tools/install-deps.sh --tests installs it)")
        sys.exit(SKIP)
    turntable([], "turn.mp4")
    p = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                        "stream=nb_read_frames,width,height", "-of", "csv=p=0", os.path.join(SCRATCH, "turn.mp4")],
                       capture_output=True, text=True)
    fields = p.stdout.strip().split(",")
    if p.returncode != 0 or fields != [str(SIZE), str(SIZE), str(FRAMES)]:
        fail("the video is not %d frames of %dx%d: %s %s" % (FRAMES, SIZE, SIZE, p.stdout.strip(), p.stderr.strip()))
    if os.path.exists(os.path.join(SCRATCH, "turn.mp4.partial.mp4")):
        fail("the partial video was left behind")
    print("video: %s frames of %sx%s" % (fields[2], fields[0], fields[1]))


CASES = {"model": case_model, "environment": case_environment, "video": case_video}

if __name__ == "__main__":
    os.makedirs(SCRATCH, exist_ok=True)
    CASES[sys.argv[4]]()
