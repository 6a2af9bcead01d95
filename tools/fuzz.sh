#!/bin/sh
# Runs every libFuzzer harness of fuzz/ for a number of executions and prints, per harness, the
# executions, crashes and coverage (docs/testing.md). Builds them first with clang 16 in
# build-fuzz/ (-DDTOADQ_FUZZ=ON: AddressSanitizer, UndefinedBehaviorSanitizer, libFuzzer).
#   sh tools/fuzz.sh [EXECUTIONS (default 1000000)] [HARNESS ...]   (harnesses: preset scene environment cli_options mtlx gltf)
# New inputs go to build-fuzz/corpus/NAME (seeded from fuzz/corpus/NAME); an input that crashes is
# copied into fuzz/corpus/NAME/ so that the test run replays it from then on: commit it with the fix.
set -eu
cd "$(dirname "$0")/.."
runs=${1:-1000000}
[ $# -gt 0 ] && shift
harnesses=${*:-"preset scene environment cli_options mtlx gltf"}
build=build-fuzz
cxx=$(command -v clang++-16 || command -v clang++ || true)
[ -n "$cxx" ] || { echo "fuzz.sh: clang++-16 is needed (sh tools/install-deps.sh --fuzz installs it)" >&2; exit 1; }

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" -DDTOADQ_FUZZ=ON ${DTOADQ_FUZZ_CMAKE_ARGS:-} >/dev/null
targets=""
for h in $harnesses; do targets="$targets fuzz_$h"; done
# shellcheck disable=SC2086
cmake --build "$build" -j"${JOBS:-$(nproc)}" --target $targets

summary=""
status=0
for h in $harnesses; do
  case $h in
    scene) max_len=65536 ;;
    preset | mtlx | gltf) max_len=8192 ;;
    environment) max_len=4096 ;;
    *) max_len=1024 ;;
  esac
  dict=""
  [ -f "fuzz/$h.dict" ] && dict="-dict=fuzz/$h.dict"
  work="$build/corpus/$h"
  crashes="$build/crashes/$h"
  mkdir -p "$work" "$crashes"
  log="$build/fuzz_$h.log"
  start=$(date +%s)
  # shellcheck disable=SC2086
  if "$build/fuzz/fuzz_$h" -runs="$runs" -max_len="$max_len" -timeout=20 -rss_limit_mb=4096 -print_final_stats=1 \
       -artifact_prefix="$crashes/" $dict "$work" "fuzz/corpus/$h" >"$log" 2>&1; then :; else status=1; fi
  seconds=$(( $(date +%s) - start ))
  executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  coverage=$(grep -o 'cov: [0-9]* ft: [0-9]*' "$log" | tail -n 1)
  found=0
  for f in "$crashes"/*; do
    [ -f "$f" ] || continue
    found=$((found + 1))
    cp "$f" "fuzz/corpus/$h/"
    echo "fuzz.sh: $h: $(basename "$f") copied into fuzz/corpus/$h/ (see $log)" >&2
  done
  [ "$found" -eq 0 ] || status=1
  summary="$summary$(printf '%-12s %12s %8s   %-24s %6s s' "$h" "${executions:-?}" "$found" "${coverage:-?}" "$seconds")
"
done
printf '%-12s %12s %8s   %-24s %8s\n' harness executions crashes "coverage (edges, features)" time
printf '%s' "$summary"
exit $status
