#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Builds the libFuzzer targets (Testing/Fuzz) with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer in ./build-fuzz, replays every input that once failed
# (Testing/Fuzz/Regressions/<target>/), then fuzzes each target for SECONDS (default 30;
# LABELMESHER_JOBS targets at a time, default 2) from its seed corpus
# (Testing/Fuzz/Corpus/<target>/). The corpus a run grows stays in
# build-fuzz/corpus/<target>/, so a longer run later starts where this one stopped; findings go
# to build-fuzz/findings/. Prints each target's executions per second and coverage; exits 1 on
# any finding.
#   bash Resources/Scripts/run-fuzzers.sh [SECONDS] [TARGET...]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/../.."
seconds="${1:-30}"
shift || true
build=build-fuzz
all=(fuzz_label_validation fuzz_mesher) # the readers': run-reader-fuzzers.sh (AFL++, ITK needs GCC)
targets=("${@:-${all[@]}}")
[ ${#targets[@]} -gt 0 ] || targets=("${all[@]}")

source "$here/ccache.sh"
CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPython3_EXECUTABLE=/usr/bin/python3 -DLABELMESHER_SANITIZE=address,undefined -DLABELMESHER_BUILD_FUZZERS=ON \
  -DLABELMESHER_BUILD_TESTING=OFF -DLABELMESHER_BUILD_BENCHMARKS=OFF -DLABELMESHER_WRAP_PYTHON=OFF \
  -DLABELMESHER_BUILD_GUI=OFF "${labelmesher_ccache[@]}" >/dev/null
cmake --build "$build" -j "${LABELMESHER_JOBS:-2}" --target "${targets[@]}"

export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/Resources/Sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
mkdir -p "$build/findings"
# One target: its pinned inputs, then SECONDS of fuzzing; prints one line; fails on a finding.
fuzz_target() {
  local t="$1" name seeds work regressions log result status=0
  name="${t#fuzz_read_}"
  name="${name#fuzz_}"
  seeds="Testing/Fuzz/Corpus/$name"
  work="$build/corpus/$name"
  mkdir -p "$work"
  regressions="Testing/Fuzz/Regressions/$name"
  if [ -d "$regressions" ] && [ -n "$(ls -A "$regressions")" ]; then
    if ! "$build/bin/$t" -runs=1 "$regressions"/* >"$build/findings/$t-regressions.log" 2>&1; then
      echo "run-fuzzers: $t fails on a pinned input (see $build/findings/$t-regressions.log)"
      status=1
    fi
  fi
  log="$build/findings/$t.log"
  if "$build/bin/$t" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=3072 -print_final_stats=1 \
       -artifact_prefix="$build/findings/$t-" "$work" "$seeds" >"$log" 2>&1; then
    result=ok
  else
    result="FINDING (see $log)"
    status=1
  fi
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo 0)
  printf 'run-fuzzers: %-24s %8s runs  %6s/s  cov %6s  corpus %5s  %s\n' "$t" "$runs" "$rate" "$cov" \
    "$(ls "$work" | wc -l)" "$result"
  return "$status"
}
# The targets run side by side, LABELMESHER_JOBS (default 2) at a time: each is one process.
source "$here/job-pool.sh"
for t in "${targets[@]}"; do
  pool_run "${LABELMESHER_JOBS:-2}" fuzz_target "$t"
done
pool_wait
exit "$pool_status"
