#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The project's test command (README), in two tiers:
#
#   bash Resources/Scripts/run-tests.sh        the fast tier: installs the Debian packages, builds
#       ./build and runs every ctest test but the large real volumes (unit, property, CLI, Python,
#       widget, GUI, Slicer-logic, example tests and the small real images).
#   bash Resources/Scripts/run-tests.sh --all  (CI, .ci/run) the fast tier, then the large real
#       volumes (label realdata-large), the sanitizer build's tests, a short run of every fuzz
#       target and the ParaView plugin's build and tests.
#
# Every tier runs even when an earlier test tier failed (only a failed set-up or build stops the
# run); the script ends with a table of each tier's time and counts, then the plain line
# "N passed, N failed", and exits 1 if anything failed. Builds go through ccache when it is
# installed (ccache.sh), so a fresh clone on a machine that built the same sources before
# re-uses their objects.
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/../.."

all=0
for argument in "$@"; do
  case "$argument" in
    --all) all=1 ;;
    -h | --help) sed -n '3,17p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "run-tests: unknown argument '$argument' (use --all or nothing)" >&2; exit 2 ;;
  esac
done

# CCACHE_BASEDIR for every compile the tiers start, the ones tests make included (the Slicer
# stand-in build), so that another clone's objects are found in the cache.
source "$here/ccache.sh"
logs="$PWD/build-logs"
mkdir -p "$logs"
names=() seconds=() passed=() failed=()
total_passed=0 total_failed=0

# Counts of one tier's log: ctest's summary lines ("... N tests failed out of M") and the fuzz
# scripts' one line per target ("run-fuzzers: TARGET ... ok" or a finding).
count_tests() {
  local log="$1" p=0 f=0 line n m
  while read -r n m; do
    f=$((f + n)); p=$((p + m - n))
  done < <(sed -n 's/.* \([0-9][0-9]*\) tests\{0,1\} failed out of \([0-9][0-9]*\).*/\1 \2/p' "$log")
  n=$(grep -cE '^run-(reader-)?fuzzers: +fuzz_[a-z_]+ .* ok$' "$log")
  m=$(grep -cE '^run-(reader-)?fuzzers: +fuzz_[a-z_]+ .*(FINDING|CRASHES|fails|failed)' "$log")
  echo "$((p + n)) $((f + m))"
}

# run_tier NAME COMMAND...: runs the command with its output shown and kept in build-logs/NAME.log;
# a command that fails without a failed test to show for it (a build, sanitizer reports) counts as
# one failure.
run_tier() {
  local name="$1"; shift
  local log="$logs/$name.log" start status counts p f
  echo "=== run-tests: $name: $*"
  start=$(date +%s)
  "$@" 2>&1 | tee "$log"
  status=${PIPESTATUS[0]}
  read -r p f < <(count_tests "$log")
  if [ "$status" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
  names+=("$name"); seconds+=($(( $(date +%s) - start ))); passed+=("$p"); failed+=("$f")
  total_passed=$((total_passed + p)); total_failed=$((total_failed + f))
  return "$status"
}

summary() {
  local i total=0
  echo
  printf '%-12s %8s %8s %8s\n' tier time passed failed
  for i in "${!names[@]}"; do
    total=$((total + seconds[i]))
    printf '%-12s %5d:%02d %8d %8d\n' "${names[i]}" $((seconds[i] / 60)) $((seconds[i] % 60)) "${passed[i]}" "${failed[i]}"
  done
  printf '%-12s %5d:%02d %8d %8d\n' total $((total / 60)) $((total % 60)) "$total_passed" "$total_failed"
  echo "$total_passed passed, $total_failed failed"
}

# A failed set-up or build leaves nothing to test.
run_tier setup bash "$here/install-dependencies.sh" || { summary; exit 1; }
run_tier build bash "$here/build.sh" || { summary; exit 1; }
run_tier tests ctest --test-dir build --output-on-failure -j2 -LE realdata-large
if [ "$all" -eq 1 ]; then
  # The large volumes two at a time: a run is on one core for much of its time (reading, setup,
  # writing), so two side by side take 15 minutes where one after the other take more.
  run_tier large ctest --test-dir build --output-on-failure -j2 -L realdata-large
  # ASan, LSan and UBSan on the unit and CLI tests and a quarter of the property tests.
  run_tier sanitizers bash "$here/run-sanitizer-tests.sh" 4
  # Every libFuzzer and AFL++ target for 30 s, after replaying the inputs that once failed.
  run_tier fuzz bash "$here/run-fuzzers.sh" 30
  run_tier fuzz-readers bash "$here/run-reader-fuzzers.sh" 30
  # The ParaView plugin against ParaView's VTK, then its tests (pvbatch, GUI).
  run_tier paraview bash -c "bash '$here/build-paraview-plugin.sh' &&
    ctest --test-dir build-paraview/build --output-on-failure"
fi
summary
[ "$total_failed" -eq 0 ]
