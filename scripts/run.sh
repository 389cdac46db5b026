#!/usr/bin/env bash
# Sets up a fresh machine, builds cetview and runs it on the built-in demo: the most complete thing
# the build has (the window viewer where there is a display, else a headless render, else an export,
# else the triangulator on the sample .poly). Extra arguments go to cetview instead.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build --parallel 2 --target cetview
exe=build/viewer/cetview
if [ $# -gt 0 ]; then exec "$exe" "$@"; fi
mkdir -p out
commands=$("$exe" --help)
has() { grep -qE "^\s+$1\b" <<<"$commands"; }
if has view && [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec "$exe" view demo
elif has render; then
  "$exe" render demo -o out/demo.png --levels
  echo "wrote out/demo.png (and one PNG per level)"
elif has export; then
  "$exe" export demo -o out/demo.glb
  echo "wrote out/demo.glb"
else
  "$exe" cdt tests/cet/data/flange.poly -o out/flange
fi
