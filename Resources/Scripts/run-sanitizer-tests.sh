#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Builds LabelMesher with AddressSanitizer (LeakSanitizer on) and UndefinedBehaviorSanitizer in
# ./build-sanitize (GCC; only the programs its tests run: no benchmarks, no Python wrapping, no
# Qt, no examples) and runs the unit and CLI
# tests there, and every PROPERTY_STRIDE-th property test (default 4: about a quarter of the
# random images). Every report goes to a file under build-sanitize/reports; the script fails
# when a test fails or when any report was written, even by a program whose failure a test
# expected. Third-party leaks only are suppressed (Resources/Sanitizers/lsan.supp).
# Usage: bash Resources/Scripts/run-sanitizer-tests.sh [PROPERTY_STRIDE]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/../.."
stride="${1:-4}"
build=build-sanitize

source "$here/ccache.sh"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPython3_EXECUTABLE=/usr/bin/python3 \
  -DLABELMESHER_SANITIZE=address,undefined -DLABELMESHER_BUILD_BENCHMARKS=OFF \
  -DLABELMESHER_WRAP_PYTHON=OFF -DLABELMESHER_BUILD_GUI=OFF "${labelmesher_ccache[@]}"
# Only what the unit, CLI and property tests run: the C++ test programs, the CLI, the scan and
# the MPI piece exchange (not the example program, whose tests this script does not run).
targets=(labelmesher labelmesher_property_scan MPIPieceExchange)
while IFS= read -r source; do
  targets+=("$(basename "$source" .cxx)")
done < <(find Testing/Cxx -name 'Test*.cxx' | sort)
cmake --build "$build" -j "${LABELMESHER_JOBS:-2}" --target "${targets[@]}"

reports="$PWD/$build/reports"
rm -rf "$reports"
mkdir -p "$reports"
# Distinct exit codes: a finding never looks like the CLI's own failure statuses (1, 2).
export ASAN_OPTIONS="log_path=$reports/asan:exitcode=86:detect_leaks=1:halt_on_error=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1"
export UBSAN_OPTIONS="log_path=$reports/ubsan:exitcode=87:halt_on_error=1:print_stacktrace=1"
# use_tls=0: GCC 12's LeakSanitizer crashes ("Tracer caught signal 11", then "LeakSanitizer has
# encountered a fatal error") while it scans a dynamic TLS block of Debian 12's glibc, on every
# run that reads a VTI (VTK's SMP tools load TBB's libraries then). Not scanning thread-local
# storage can only report more leaks, never fewer (it is a source of roots, not of blocks); the
# one it adds, glibc's own dlopen scope array, is suppressed in lsan.supp.
export LSAN_OPTIONS="suppressions=$PWD/Resources/Sanitizers/lsan.supp:print_suppressions=0:exitcode=88:use_tls=0"

status=0
ctest --test-dir "$build" -L "unit|cli" --output-on-failure -j2 || status=1
ctest --test-dir "$build" -L property -I ",,$stride" --output-on-failure -j2 || status=1

found=$(find "$reports" -type f | wc -l)
if [ "$found" -ne 0 ]; then
  echo "run-sanitizer-tests: $found sanitizer report(s):"
  for f in "$reports"/*; do
    echo "== $f"
    head -n 40 "$f"
  done
  status=1
else
  echo "run-sanitizer-tests: no sanitizer reports"
fi
exit "$status"
