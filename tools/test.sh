#!/usr/bin/env bash
# Builds ferrodyn and runs its test suite.
#   tools/test.sh              the whole suite: the default tests, then the slow validations
#                              (ctest label "slow"), build dir build/
#   tools/test.sh --fast       the default tests only (everything not labelled "slow")
#   tools/test.sh --slow       the slow validations only
#   tools/test.sh --sanitize   the default tests under ASan+UBSan (assertions on, -O1), build dir
#                              build-asan/ (the Python module is left out: the interpreter is not
#                              instrumented)
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh

build=build
cmake_args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo)
run_default=1
run_slow=1
for arg in "$@"; do
  case "$arg" in
    --sanitize) build=build-asan; run_slow=0
                # Assertions on (Debug) at -O1: Eigen's kernels at -O0 make the whole-vehicle
                # tests 20-30x slower, while -O1 keeps ASan's and UBSan's reports exact; line
                # tables (-g1) are all their stack traces read.
                cmake_args=(-DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1"
                            "-DCMAKE_C_FLAGS_DEBUG=-O1 -g1" -DFERRO_SANITIZE=ON
                            -DFERRO_BUILD_BENCH=OFF -DFERRO_BUILD_PYTHON=OFF) ;;
    --fast) run_slow=0 ;;
    --slow) run_default=0 ;;
    *) echo "test.sh: unknown option '$arg' (allowed: --fast, --slow, --sanitize)" >&2; exit 2 ;;
  esac
done
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B "$build" -G Ninja "${cmake_args[@]}"
cmake --build "$build" -j "$jobs"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
if [ "$run_default" = 1 ]; then
  echo "== default tests ($build)"
  ctest --test-dir "$build" --output-on-failure -j "$jobs" -LE slow
fi
if [ "$run_slow" = 1 ]; then
  echo "== slow validations ($build, ctest -L slow)"
  ctest --test-dir "$build" --output-on-failure -j "$jobs" -L slow
fi
