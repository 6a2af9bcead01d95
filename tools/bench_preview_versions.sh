#!/usr/bin/env bash
# Equal-time preview error of every preset, this build against another dtoadq binary
# (docs/materials.md, "Preview with and without energy compensation"). Per preset and version it renders the preview twice at SPP samples per pixel
# with two seeds, A and B, interleaving the versions so that load changes on a shared machine hit
# both alike. Each version is measured against itself: with two independent unbiased images,
# E[(A - B)^2] = 2 sigma^2, so sigma_N = sqrt(mean((A - B)^2) / 2) is the RMSE of an N-sample preview
# against its own infinite-sample reference (with energy compensation the reference itself changes,
# so a shared reference would count the change as error). Equal-time RMSE at time T is then
# sigma_N sqrt(N t_spp / T); the ratio new/old printed is sigma_new/sigma_old * sqrt(t_new/t_old),
# with t the CPU time per sample (kernel build and file writing excluded) of the same runs.
#   tools/bench_preview_versions.sh OLD_BINARY OLD_PRESETS_DIR [SIZE] [SPP]   (PRESET_FILES="a.json b.json" picks presets, NEW_BIN another new binary)
# needs oiiotool (OpenImageIO's tools, in tools/install-deps.sh). Figures, not a test.
set -euo pipefail
old_bin=${1:?old dtoadq binary}
old_presets=${2:?old presets folder}
size=${3:-64x64}
spp=${4:-128}
root=$(cd "$(dirname "$0")/.." && pwd)
new_bin=${NEW_BIN:-$root/build/cli/dtoadq}
env=$root/envmaps/courtyard.exr
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# render BINARY TAG SEED PRESET_DIR PRESET [SPP]: prints the CPU seconds (user + system, all threads)
# of the run. CPU time, not wall time: on a shared machine other work stretches the wall clock but
# hardly the CPU time a render needs.
render() {
    local bin=$1 tag=$2 seed=$3 presets=$4 preset=$5 n=${6:-$spp}
    local TIMEFORMAT='%U %S'
    { time "$bin" preview --material "$presets/$preset.json" --env "$env" --size "$size" --spp "$n" --seed "$seed" \
        --quiet -o "$work/$tag-$seed.exr" >/dev/null 2>&1; } 2>&1 | awk '{print $1 + $2}'
}
# sigma A B: per-pixel standard deviation of one image, sqrt(mean over pixels and RGB of (A - B)^2 / 2)
sigma() {
    oiiotool "$1" --ch R,G,B "$2" --ch R,G,B --sub --powc 2 --printstats 2>/dev/null |
        awk '/Stats Avg/ {print sqrt(($3 + $4 + $5) / 3 / 2)}'
}

printf "preview %s, %d spp x 2 seeds per version, courtyard.exr; new %s, old %s\n" "$size" "$spp" "$new_bin" "$old_bin"
printf "%-20s %10s %10s %13s %13s %8s %8s\n" preset rmse_old rmse_new cpu_s/spp_old cpu_s/spp_new t_ratio eqtime_new/old
for file in ${PRESET_FILES:-"$root"/presets/*.json}; do
    p=$(basename "$file" .json)
    [ -f "$old_presets/$p.json" ] || continue
    # the CPU time of a sample: two full runs less two short ones (kernel build, loading, writing), interleaved
    to1=$(render "$old_bin" old 1 "$old_presets" "$p"); tn1=$(render "$new_bin" new 1 "$root/presets" "$p")
    tn0=$(render "$new_bin" short 3 "$root/presets" "$p" 1); to0=$(render "$old_bin" short 3 "$old_presets" "$p" 1)
    tn2=$(render "$new_bin" new 2 "$root/presets" "$p"); to2=$(render "$old_bin" old 2 "$old_presets" "$p")
    to3=$(render "$old_bin" short 4 "$old_presets" "$p" 1); tn3=$(render "$new_bin" short 4 "$root/presets" "$p" 1)
    so=$(sigma "$work/old-1.exr" "$work/old-2.exr"); sn=$(sigma "$work/new-1.exr" "$work/new-2.exr")
    awk -v p="$p" -v so="$so" -v sn="$sn" -v to="$to1+$to2-$to0-$to3" -v tn="$tn1+$tn2-$tn0-$tn3" -v n="$spp" 'BEGIN {
        split(to, a, "[+-]"); split(tn, b, "[+-]");
        t_old = (a[1] + a[2] - a[3] - a[4]) / (2 * (n - 1)); t_new = (b[1] + b[2] - b[3] - b[4]) / (2 * (n - 1));
        printf "%-20s %10.4g %10.4g %13.3g %13.3g %8.2f %8.2f\n", p, so, sn, t_old, t_new, t_new / t_old, sn / so * sqrt(t_new / t_old) }'
done
