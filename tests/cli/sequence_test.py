#!/usr/bin/env python3
"""End-to-end test of `dtoadq render --frames A:B --fps N` (on the host renderer, tiny images): frame k
of a sequence equals a single render at the scene time k / N bit for bit; a sequence run again skips
its finished frames (their files untouched) and continues an incomplete one to the render one run
makes; a frame file of another render stops it with one line; --video makes a video with one frame per
rendered frame, and without the ffmpeg program it stops with one line and keeps the frames.

usage: sequence_test.py DTOADQ SCENE SCRATCH_DIR CASE   (CASE: identity, resume, video). Exit 77: skipped.
"""
import os
import shutil
import subprocess
import sys

SKIP = 77
EXE, SCENE, SCRATCH = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), os.path.abspath(sys.argv[3])
COMMON = ["--device", "host", "--size", "24x16", "--quiet"]


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def dtoadq(args, status=0):
    p = subprocess.run([EXE, "render", SCENE] + COMMON + args, cwd=SCRATCH, capture_output=True, text=True, timeout=300)
    if p.returncode != status:
        fail("dtoadq render %s exited %d (expected %d): %s" % (" ".join(args), p.returncode, status, p.stderr.strip()))
    return p


def identical(a, b):
    """Whether two EXRs hold the same numbers in every channel (the image and the film)."""
    p = subprocess.run(["oiiotool", "--fail", "0", "--warn", "0", a, b, "--diff"], cwd=SCRATCH, capture_output=True, text=True)
    return p.returncode == 0


def stamp(path):
    s = os.stat(os.path.join(SCRATCH, path))
    return (s.st_ino, s.st_mtime_ns)


def case_identity():
    # frames 1 and 2 at 4 frames/s: the scene times 0.25 and 0.5
    dtoadq(["--spp", "2", "--frames", "1:3", "--fps", "4", "-o", "f_%04d.exr"])
    dtoadq(["--spp", "2", "--scene-time", "0.5", "-o", "single.exr"])
    if not identical("f_0002.exr", "single.exr"):
        fail("frame 2 at 4 frames/s is not the single render at t = 0.5")
    if identical("f_0001.exr", "single.exr"):
        fail("frame 1 equals the render at t = 0.5: the scene does not move, so the comparison shows nothing")
    info = subprocess.run(["oiiotool", "--info", "-v", "f_0002.exr"], cwd=SCRATCH, capture_output=True, text=True).stdout
    for expected in ['dtoadq:frame: 2', 'dtoadq:fps: "4"', 'dtoadq:scene_time: "0.5"']:
        if expected not in info:
            fail("frame 2's header lacks %s" % expected)
    print("identity: frame 2 equals the render at t = 0.5 bit for bit, frame 1 differs")


def case_resume():
    # an incomplete frame 1 (1 of 2 samples, as a Ctrl-C leaves one), then the sequence
    dtoadq(["--spp", "1", "--frames", "1:2", "--fps", "4", "-o", "f_%04d.exr"])
    out = dtoadq(["--spp", "2", "--frames", "0:3", "--fps", "4", "-o", "f_%04d.exr"]).stdout
    if "frames 0 to 2: 2 rendered, 1 continued, 0 finished before" not in out:
        fail("the first run did not render frames 0 and 2 and continue frame 1: %s" % out)
    dtoadq(["--spp", "2", "--scene-time", "0.25", "-o", "one_run.exr"])
    if not identical("f_0001.exr", "one_run.exr"):
        fail("frame 1 continued from 1 to 2 samples is not the render one run makes")
    stamps = [stamp("f_%04d.exr" % k) for k in range(3)]
    out = dtoadq(["--spp", "2", "--frames", "0:3", "--fps", "4", "-o", "f_%04d.exr"]).stdout
    if "frames 0 to 2: 0 rendered, 0 continued, 3 finished before" not in out:
        fail("the second run rendered again: %s" % out)
    if [stamp("f_%04d.exr" % k) for k in range(3)] != stamps:
        fail("the second run rewrote a finished frame's file")
    # a frame file of another render (another seed) is neither skipped nor overwritten
    dtoadq(["--spp", "2", "--seed", "5", "--frames", "3:4", "--fps", "4", "-o", "f_%04d.exr"])
    before = stamp("f_0003.exr")
    p = dtoadq(["--spp", "2", "--frames", "0:4", "--fps", "4", "-o", "f_%04d.exr"], status=2)
    line = p.stderr.strip()
    if "\n" in line or not line.startswith('dtoadq: error: f_0003.exr: dtoadq:seed: "5", but this render has "0"'):
        fail("a frame of another render: %s" % line)
    if stamp("f_0003.exr") != before:
        fail("a frame of another render was overwritten")
    print("resume: an incomplete frame continued to the one-run render, finished frames skipped, another render's frame refused")


def case_video():
    dtoadq(["--spp", "1", "--frames", "2:5", "--fps", "4", "-o", "f_%04d.exr"])
    # no ffmpeg on PATH: one line, the frames kept
    stamps = [stamp("f_%04d.exr" % k) for k in range(2, 5)]
    env = dict(os.environ, PATH=SCRATCH)
    p = subprocess.run([EXE, "render", SCENE] + COMMON + ["--spp", "1", "--frames", "2:5", "--fps", "4", "-o", "f_%04d.exr", "--video", "v.mp4"],
                       cwd=SCRATCH, capture_output=True, text=True, env=env, timeout=300)
    line = p.stderr.strip()
    if p.returncode != 2 or "\n" in line or not line.startswith("dtoadq: error: --video: needs the ffmpeg program"):
        fail("without ffmpeg: exit %d, %s" % (p.returncode, line))
    if [stamp("f_%04d.exr" % k) for k in range(2, 5)] != stamps or os.path.exists(os.path.join(SCRATCH, "v.mp4")):
        fail("without ffmpeg the frames changed or a video appeared")
    if not shutil.which("ffmpeg") or not shutil.which("ffprobe"):
        print("SKIP: no ffmpeg (tools/install-deps.sh installs it)")
        sys.exit(SKIP)
    out = dtoadq(["--spp", "1", "--frames", "2:5", "--fps", "4", "-o", "f_%04d.exr", "--video", "v.mp4"]).stdout
    if "0 rendered, 0 continued, 3 finished before" not in out:
        fail("the video run rendered the finished frames again: %s" % out)
    p = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                        "stream=nb_read_frames,width,height,r_frame_rate", "-of", "csv=p=0", os.path.join(SCRATCH, "v.mp4")],
                       capture_output=True, text=True)
    fields = p.stdout.strip().split(",")
    if p.returncode != 0 or fields != ["24", "16", "4/1", "3"]:
        fail("the video is not 3 frames of 24x16 at 4 frames/s: %s %s" % (p.stdout.strip(), p.stderr.strip()))
    if os.path.exists(os.path.join(SCRATCH, "v.mp4.partial.mp4")):
        fail("the partial video was left behind")
    print("video: %s frames of %sx%s at %s frames/s" % (fields[3], fields[0], fields[1], fields[2]))


CASES = {"identity": case_identity, "resume": case_resume, "video": case_video}

if __name__ == "__main__":
    shutil.rmtree(SCRATCH, ignore_errors=True)
    os.makedirs(SCRATCH)
    CASES[sys.argv[4]]()
