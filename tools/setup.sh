#!/usr/bin/env bash
# Installs every Debian package Throng needs to build, run, test and fuzz. Safe to run
# again: it only installs what is missing. Debian 12 (bookworm); run as root or with sudo.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config clang libclang-rt-14-dev python3
  # Vulkan: loader and headers (with Vulkan-Hpp), lavapipe, validation layers, shader compiler
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools glslang-tools
  # libraries
  libglm-dev libglfw3-dev libstb-dev nlohmann-json3-dev libimgui-dev libcli11-dev
  # video: FFmpeg's libraries (H.264 through libx264) for MP4 output
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev
  # tests: GoogleTest, a display server, an X11 client library and xdotool (real key presses
  # and clicks through XTest) for window tests, three.js for the FK cross-check
  libgtest-dev xvfb xauth libx11-dev xdotool libjs-three
  # tests: FFmpeg's tools decode the videos; GNU parallel runs split renders
  ffmpeg parallel
  # benchmark plots
  gnuplot-nox
)
# Node runs the three.js cross-check. Debian's nodejs package would clash with a Node
# already installed from elsewhere, so it is added only when there is no node at all.
command -v node >/dev/null 2>&1 || packages+=(nodejs)

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages are installed"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null 2>&1 || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "setup: installing ${missing[*]}"
$sudo apt-get update -qq
$sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
