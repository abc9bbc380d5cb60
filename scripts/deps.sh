#!/usr/bin/env bash
# Installs the Debian 12 packages raymarching needs, only if some are missing.
#   scripts/deps.sh build   what building and running needs
#   scripts/deps.sh test    that, plus what the tests need (Xvfb, xdotool, ...)
set -euo pipefail

build_packages=(
  cmake ninja-build g++ pkg-config
  libglfw3-dev libglm-dev glslang-dev glslang-tools libopenimageio-dev libegl-dev libepoxy-dev
  libx11-dev  # GLX contexts for the window's builders
  libcli11-dev libgtest-dev libgmock-dev nlohmann-json3-dev libimgui-dev
  libfontconfig-dev fonts-dejavu-core  # the interface's letters past ASCII
  libfarmhash-dev  # a take's fingerprints of its sources
  libegl-mesa0 libgl1-mesa-dri  # Mesa: EGL and llvmpipe, for machines without a GPU
)
test_packages=(xvfb xauth xdotool twm x11-apps openimageio-tools python3 git clang libclang-rt-14-dev ffmpeg parallel
  slurmctld slurmd slurm-client munge  # a one-node Slurm that tests/farm/slurm_test.py starts
  valgrind  # tests/bench/instruction_count.py: a scene's cost, counted, not timed
  gdb  # the backtrace of a window that crashed in an end-to-end test
  fonts-wqy-microhei)  # Chinese letters, which the interface adds when a text holds them

wanted=("${build_packages[@]}")
if [[ "${1:-build}" == test ]]; then wanted+=("${test_packages[@]}"); fi

missing=()
for p in "${wanted[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "installing: ${missing[*]}" >&2
sudo=()
[[ $(id -u) -ne 0 ]] && sudo=(sudo)
"${sudo[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
