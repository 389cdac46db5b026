#!/usr/bin/env bash
# Sets up a fresh machine, builds everything (Release, warnings as errors) and runs every test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCETVIEW_WERROR=ON
cmake --build build --parallel 2
ctest --test-dir build --output-on-failure --parallel 2 --timeout 900
