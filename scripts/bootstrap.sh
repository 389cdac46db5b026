#!/usr/bin/env bash
# Installs every Debian package cetview's build, tests, benchmarks and viewer need.
# Idempotent: packages already present are left alone; runs as root or through sudo.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config clang libclang-rt-14-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev libcgal-dev
  # command line, logging, images, mesh utilities
  libcli11-dev libspdlog-dev libfmt-dev libstb-dev libmeshoptimizer-dev
  # OpenCASCADE 7.6 and its sample models
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-ocaf-dev libocct-data-exchange-dev libocct-visualization-dev libtbb-dev occt-misc
  # Vulkan: loader, lavapipe, shader compiler, validation
  libvulkan-dev mesa-vulkan-drivers glslang-tools vulkan-validationlayers vulkan-tools
  # window and UI
  libglfw3-dev libglm-dev libimgui-dev libxcb1-dev xvfb xauth
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "bootstrap: all ${#packages[@]} packages present"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update
"${sudo[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
echo "bootstrap: installed ${#missing[@]} packages"
