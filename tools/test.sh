#!/usr/bin/env bash
# Builds ferrodyn and runs its test suite.
#   tools/test.sh              default suite (everything not labelled "slow"), build dir build/
#   tools/test.sh --sanitize   the same suite under ASan+UBSan, build dir build-asan/
#   tools/test.sh --slow       only the slow validations (ctest -L slow)
#   tools/test.sh --all        default suite and slow validations
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh

build=build
cmake_args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo)
ctest_args=(-LE slow)
for arg in "$@"; do
  case "$arg" in
    --sanitize) build=build-asan; cmake_args=(-DCMAKE_BUILD_TYPE=Debug -DFERRO_SANITIZE=ON -DFERRO_BUILD_BENCH=OFF) ;;
    --slow) ctest_args=(-L slow) ;;
    --all) ctest_args=() ;;
    *) echo "test.sh: unknown option '$arg' (allowed: --sanitize, --slow, --all)" >&2; exit 2 ;;
  esac
done
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B "$build" -G Ninja "${cmake_args[@]}"
cmake --build "$build" -j "$jobs"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
ctest --test-dir "$build" --output-on-failure -j "$jobs" "${ctest_args[@]}"
