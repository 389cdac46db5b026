#!/usr/bin/env bash
# Sets up a fresh machine, builds everything (Release, warnings as errors) and runs every test suite,
# then the sanitizer runs: every suite under AddressSanitizer + UndefinedBehaviorSanitizer, and the
# progressive stream (worker threads, rings, cancellation), the threaded tessellation (work sharing)
# and the fallback's BRepMesh thread under ThreadSanitizer, each in its own tree.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCETVIEW_WERROR=ON
cmake --build build --parallel 2
ctest --test-dir build --output-on-failure --parallel 2 --timeout 900

echo "== AddressSanitizer + UndefinedBehaviorSanitizer: every suite =="
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCETVIEW_CORE_ONLY=OFF \
  -DCETVIEW_SANITIZE=address -DCETVIEW_BUILD_BENCH=OFF -DCETVIEW_WERROR=ON
cmake --build build-asan --parallel 2
LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0" \
  UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
  ctest --test-dir build-asan --output-on-failure --parallel 2 --timeout 900

echo "== ThreadSanitizer: progressive stream, threaded tessellation, work sharing, fallback thread =="
cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCETVIEW_SANITIZE=thread \
  -DCETVIEW_BUILD_BENCH=OFF -DCETVIEW_WERROR=ON
cmake --build build-tsan --parallel 2 --target stream_tests brep_tests
TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" build-tsan/tests/stream/stream_tests
TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" build-tsan/tests/brep/brep_tests \
  --gtest_filter='WorkerPool.*:WorkSharing.*:Progressive.*:Isolation.*-Isolation.AFaceThatFallsBackAfterAnEdgeStoppedSaysBoth'
