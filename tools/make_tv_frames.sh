#!/bin/sh
# The TV room's screen (scenes/tv_room.json): one second of FFmpeg's test pattern (colour bars, a
# scrolling gradient and a counter of hundredths of a second), 12 frames of 96 x 54 at 12 fps, as
# the PNG sequence the scene plays (screen_0000.png ... screen_0011.png)
# and the same frames in an .mp4 (H.264 in RGB, lossless, so that each decoded frame equals its PNG
# to the byte: tests/test_frame_source.cpp holds the video reader to that). Run it from the
# repository's root; it needs the ffmpeg program (sh tools/install-deps.sh installs it).
set -eu
out=scenes/tv_room
mkdir -p "$out"
rm -f "$out"/screen_*.png "$out"/screen.mp4
ffmpeg -loglevel error -f lavfi -i "testsrc=size=96x54:rate=12:decimals=2" -frames:v 12 -start_number 0 "$out/screen_%04d.png"
ffmpeg -loglevel error -framerate 12 -start_number 0 -i "$out/screen_%04d.png" -c:v libx264rgb -qp 0 -pix_fmt rgb24 "$out/screen.mp4"
ls -l "$out"
