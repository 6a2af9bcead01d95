#!/bin/sh
# Installs the Debian 12 packages DTOADQ lab needs that are not installed yet (run as root, or with sudo available).
#   sh tools/install-deps.sh            the build, the main job (dtoadq report) and the commands' own
#                                       programs (FFmpeg, for render --video and the turntable's video)
#   sh tools/install-deps.sh --tests    and what the test run needs besides: a virtual display for the
#                                       viewer's tests, a browser and an HTML parser for the report page's,
#                                       and the virtual environment .venv/
#                                       with MaterialX and jsonschema from PyPI for the interchange formats'
#                                       validity check (tests/check_interchange_validity.py)
#   sh tools/install-deps.sh --fuzz     and clang 16 with its libFuzzer runtime, for tools/fuzz.sh
# Each set only what it needs: on a fresh machine every package is a download and an unpack, and the
# main job and the test run count that time too.
set -eu
venv=0
packages="cmake g++ make pkg-config ca-certificates
pocl-opencl-icd ocl-icd-opencl-dev opencl-headers opencl-clhpp-headers clinfo
libopenimageio-dev openimageio-tools libopenexr-dev
libglfw3-dev libimgui-dev libglm-dev catch2 nlohmann-json3-dev libcli11-dev libnlopt-dev libpugixml-dev
python3 python3-matplotlib python3-numpy ffmpeg"
for set in "$@"; do
  case $set in
    --tests) packages="$packages xvfb xauth libgl1-mesa-dri chromium python3-html5lib python3-venv"; venv=1 ;;
    --fuzz) packages="$packages clang-16 libclang-rt-16-dev" ;;
    *) echo "install-deps: unknown option $set (--tests, --fuzz)" >&2; exit 2 ;;
  esac
done
missing=""
for p in $packages; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -z "$missing" ]; then
  echo "install-deps: all packages present"
else
  echo "install-deps: installing$missing"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -q
  # shellcheck disable=SC2086
  $sudo apt-get install -y -q --no-install-recommends $missing
fi
# The formats' own validators, pinned: MaterialX's document validation and a JSON Schema checker
# for glTF (docs/interchange.md). Made once; a present environment with both is kept.
if [ "$venv" -eq 1 ]; then
  root="$(cd "$(dirname "$0")/.." && pwd)"
  if ! "$root/.venv/bin/python3" -c "import MaterialX, jsonschema" 2>/dev/null; then
    echo "install-deps: making $root/.venv with materialx and jsonschema"
    python3 -m venv "$root/.venv"
    "$root/.venv/bin/pip" install -q materialx==1.39.5 jsonschema==4.26.0
  fi
fi
