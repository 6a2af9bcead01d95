#!/bin/sh
# Installs the Debian 12 packages DTOADQ lab needs that are not installed yet (run as root, or with sudo available).
set -eu
packages="cmake g++ make pkg-config ca-certificates
pocl-opencl-icd ocl-icd-opencl-dev opencl-headers opencl-clhpp-headers clinfo
libopenimageio-dev openimageio-tools libopenexr-dev
libglfw3-dev libimgui-dev libglm-dev catch2 nlohmann-json3-dev libcli11-dev libnlopt-dev
python3 python3-matplotlib python3-numpy
xvfb xauth libgl1-mesa-dri
chromium python3-html5lib
clang-16 libclang-rt-16-dev"
missing=""
for p in $packages; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -z "$missing" ]; then
  echo "install-deps: all packages present"
  exit 0
fi
echo "install-deps: installing$missing"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
# shellcheck disable=SC2086
$sudo apt-get install -y -q --no-install-recommends $missing
