#!/bin/sh
# The viewer's change-to-first-updated-frame latency, interface frame times and samples/s
# (docs/viewer.md, "Figures"): a slider drag (a burst of 21 --set changes 5 frames apart) and
# isolated changes (every 60 frames), camera and map changes (--move, where the binary has it), the viewer's samples/s against `dtoadq preview`'s, on the test model at 256x256 under envmaps/courtyard.exr,
# then `dtoadq preview` alone for the samples/s ratio. Run from the source folder:
#   tools/viewer_latency.sh build/cli/dtoadq [more viewer options]
# Needs a display or xvfb-run. Timings on a shared machine are noisy: compare binaries in one run.
set -e
DTOADQ=${1:?usage: tools/viewer_latency.sh DTOADQ [viewer options]}
shift
RUN=""
[ -z "$DISPLAY" ] && RUN="xvfb-run -a -s -screen\ 0\ 1920x1080x24"
COMMON="--material presets/gold.json --env envmaps/courtyard.exr --size 256x256 --stats"
burst=""
f=60
for i in $(seq 0 20); do
    r=$(awk "BEGIN { print 0.2 + 0.02 * $i }")
    burst="$burst --set roughness=$r@$f"
    f=$((f + 5))
done
echo "== slider drag: 21 changes 5 frames apart"
eval $RUN "$DTOADQ" view $COMMON --frames 200 $burst "$@"
echo "== isolated changes: 12 changes 60 frames apart"
iso=""
for i in $(seq 1 12); do iso="$iso --set roughness=$(awk "BEGIN { print 0.1 + 0.05 * $i }")@$((i * 60))"; done
eval $RUN "$DTOADQ" view $COMMON --frames 780 $iso "$@"
if "$DTOADQ" view --help | grep -q -- --move; then
    echo "== camera and environment: 12 changes 60 frames apart (orbit and map rotation in turn)"
    mv=""
    for i in $(seq 1 12); do
        if [ $((i % 2)) = 0 ]; then mv="$mv --move orbit=20,0@$((i * 60))"; else mv="$mv --move env_rotation=$((i * 20))@$((i * 60))"; fi
    done
    eval $RUN "$DTOADQ" view $COMMON --frames 780 $mv "$@"
fi
if "$DTOADQ" view --help | grep -q -- --window; then
    echo "== interface at 1280x800 with material, checks and lobe open, rendering (docs/viewer.md: median at most 50 ms on llvmpipe)"
    eval $RUN "$DTOADQ" view $COMMON --frames 150 --window 1280x800 --open Lobe "$@"
fi
echo "== samples/s: the viewer without changes to 8 spp, then dtoadq preview alone (same size and map)"
eval $RUN "$DTOADQ" view $COMMON --frames 10 --min-spp 8 "$@"
"$DTOADQ" preview --material presets/gold.json --env envmaps/courtyard.exr --size 256x256 --spp 8 -o /tmp/viewer_latency_preview.exr 2>&1 | tail -3
