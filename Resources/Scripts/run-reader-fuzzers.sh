#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Builds the readers' fuzz targets (Testing/Fuzz, one per format: fuzz_read_nrrd, _nhdr, _nifti,
# _metaimage, _vti, _png, _segmentation) with AFL++'s GCC mode (afl-g++, instrumented by afl-as:
# Debian's ITK headers refuse clang, so libFuzzer cannot build them, and Debian 12's GCC plugin
# afl-g++-fast aborts with "GCC and plugin have incompatible versions"), AddressSanitizer and
# UndefinedBehaviorSanitizer in ./build-afl, replays every input that once failed
# (Testing/Fuzz/Regressions/read_<format>/), then runs afl-fuzz on each target for SECONDS (default
# 30; LABELMESHER_JOBS targets at a time, default 2) from its seeds (Testing/Fuzz/Corpus/<format>/). A target's queue stays in
# build-afl/afl/<format>/ and a later run resumes it; crashes are in build-afl/afl/<format>/default/crashes/.
# Prints each target's executions, executions per second, edges covered and crashes/hangs; exits 1
# on a crash or a failing pinned input. Needs the package afl++ (install-dependencies.sh).
#   bash Resources/Scripts/run-reader-fuzzers.sh [SECONDS] [FORMAT...]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/../.."
seconds="${1:-30}"
shift || true
build=build-afl
all=(nrrd nhdr nifti metaimage vti png segmentation)
formats=("${@:-${all[@]}}")
[ ${#formats[@]} -gt 0 ] || formats=("${all[@]}")
targets=()
for f in "${formats[@]}"; do targets+=("fuzz_read_$f"); done

command -v afl-fuzz >/dev/null || { echo "run-reader-fuzzers: afl-fuzz not found (apt install afl++)" >&2; exit 1; }
export AFL_CC_COMPILER=GCC # afl-gcc/afl-g++ in afl-as mode
source "$here/ccache.sh"
CC=afl-gcc CXX=afl-g++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPython3_EXECUTABLE=/usr/bin/python3 -DLABELMESHER_SANITIZE=address,undefined -DLABELMESHER_BUILD_FUZZERS=ON \
  -DLABELMESHER_BUILD_TESTING=OFF -DLABELMESHER_BUILD_BENCHMARKS=OFF -DLABELMESHER_WRAP_PYTHON=OFF \
  -DLABELMESHER_BUILD_GUI=OFF "${labelmesher_ccache[@]}" >/dev/null
AFL_QUIET=1 cmake --build "$build" -j "${LABELMESHER_JOBS:-2}" --target "${targets[@]}"

# A machine set up for fuzzing tunes the CPU governor and core_pattern; CI's is not, and the
# results do not depend on either.
export AFL_SKIP_CPUFREQ=1 AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES=1 AFL_NO_UI=1 AFL_AUTORESUME=1
export AFL_NO_AFFINITY=1 AFL_SKIP_CRASHES=1
# One format: its pinned inputs, then SECONDS of afl-fuzz; prints one line; fails on a crash.
fuzz_format() {
  local f="$1" t="fuzz_read_$1" out regressions input stats crashes result status=0
  out="$build/afl/$f"
  mkdir -p "$out"
  regressions="Testing/Fuzz/Regressions/read_$f"
  if [ -d "$regressions" ] && [ -n "$(ls -A "$regressions")" ]; then
    for input in "$regressions"/*; do
      if ! "$build/bin/$t" "$input" >"$out/regression.log" 2>&1; then
        echo "run-reader-fuzzers: $t fails on the pinned input $input (see $out/regression.log)"
        status=1
      fi
    done
  fi
  # -V: stop after SECONDS; -m none: ASan reserves far more virtual memory than AFL's default limit.
  afl-fuzz -V "$seconds" -t 10000 -m none -i "Testing/Fuzz/Corpus/$f" -o "$out" -- "$build/bin/$t" @@ \
    >"$out/afl.log" 2>&1 || { echo "run-reader-fuzzers: afl-fuzz failed on $t (see $out/afl.log)"; return 1; }
  stats="$out/default/fuzzer_stats"
  value() { sed -n "s/^$1 *: *//p" "$stats"; }
  crashes=$(value saved_crashes)
  result=ok
  if [ "${crashes:-0}" != 0 ]; then
    result="CRASHES in $out/default/crashes"
    status=1
  fi
  printf 'run-reader-fuzzers: %-22s %9s runs %7s/s  edges %5s (%s)  hangs %s  %s\n' "$t" "$(value execs_done)" \
    "$(value execs_per_sec)" "$(value edges_found)" "$(value bitmap_cvg)" "$(value saved_hangs)" "$result"
  return "$status"
}
# The formats run side by side, LABELMESHER_JOBS (default 2) at a time: afl-fuzz is one process
# (AFL_NO_AFFINITY above lets two share the cores).
source "$here/job-pool.sh"
for f in "${formats[@]}"; do
  pool_run "${LABELMESHER_JOBS:-2}" fuzz_format "$f"
done
pool_wait
exit "$pool_status"
