#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The project's test command (README, CI): install dependencies, build, run every test,
# then the sanitizer build's tests, a short run of every fuzz target, and the ParaView plugin's
# tests. Each step must pass.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/../.."
bash "$here/install-dependencies.sh"
bash "$here/build.sh"
ctest --test-dir build --output-on-failure -j2
# AddressSanitizer, LeakSanitizer and UndefinedBehaviorSanitizer on the unit and CLI tests and a
# quarter of the property tests (build-sanitize/); any report fails.
bash "$here/run-sanitizer-tests.sh" 4
# Each libFuzzer target for 30 s from its seed corpus, after replaying the inputs that once failed.
bash "$here/run-fuzzers.sh" 30
# Each reader's AFL++ target for 30 s (build-afl/), after replaying the inputs that once failed.
bash "$here/run-reader-fuzzers.sh" 30
# The ParaView plugin: its own configure against ParaView's VTK, then its tests (pvbatch, GUI).
bash "$here/build-paraview-plugin.sh"
ctest --test-dir build-paraview/build --output-on-failure
