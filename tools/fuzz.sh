#!/usr/bin/env bash
# Fuzzes the scene loader, the profile readers and the `contact eval --batch` CSV parser with
# libFuzzer (clang, AddressSanitizer), starting from tests/fuzz/corpus/<target>/.
#
#   tools/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]     # default: 60 s, every target
#   FUZZ_RUNS=1000000 tools/fuzz.sh 0 scene            # a fixed number of executions instead
#
# Build folder: build-fuzz (FERRO_FUZZ=ON, clang). New inputs go to build-fuzz/corpus/<target>/
# (the checked-in corpus is only read); crashes to build-fuzz/crashes/<target>/. Each target's
# last lines (executions, coverage) are printed; the exit code is non-zero if any target found
# a crash. Scratch inputs go to $TMPDIR (default /dev/shm). Needs: clang and libclang-rt-14-dev
# (Debian 12).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[[ ${#targets[@]} -eq 0 ]] && targets=(scene profile batch)
build=${FUZZ_BUILD_DIR:-build-fuzz}
# The targets hand each input to the readers as a scratch file: keep those in memory (tmpfs).
if [[ -z ${TMPDIR:-} && -d /dev/shm && -w /dev/shm ]]; then export TMPDIR=/dev/shm; fi

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DFERRO_FUZZ=ON \
  -DFERRO_BUILD_BENCH=OFF ${FUZZ_CMAKE_ARGS:-} >/dev/null
cmake --build "$build" -j"${FUZZ_JOBS:-2}" --target "${targets[@]/#/fuzz_}"

status=0
for t in "${targets[@]}"; do
  mkdir -p "$build/corpus/$t" "$build/crashes/$t"
  limit=(-max_total_time="$seconds")
  [[ -n ${FUZZ_RUNS:-} ]] && limit=(-runs="$FUZZ_RUNS")
  log="$build/fuzz_$t.log"
  echo "== fuzz_$t (${limit[*]})"
  # close_fd_mask=3: the targets' own stdout/stderr (error messages) are not echoed.
  if ! "$build/tests/fuzz/fuzz_$t" "${limit[@]}" -close_fd_mask=3 -max_len=8192 -timeout=30 \
      -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix="$build/crashes/$t/" \
      "$build/corpus/$t" "tests/fuzz/corpus/$t" >"$log" 2>&1; then
    status=1
    echo "fuzz_$t: FAILED (see $log and $build/crashes/$t/)"
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb|Done [0-9]+ runs|cov:" "$log" | tail -3
done
exit $status
