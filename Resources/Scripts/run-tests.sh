#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The project's test command (README, CI): install dependencies, build, run every test,
# then build the ParaView plugin and run its tests.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/../.."
bash "$here/install-dependencies.sh"
bash "$here/build.sh"
ctest --test-dir build --output-on-failure -j2
# The ParaView plugin: its own configure against ParaView's VTK, then its tests (pvbatch, GUI).
bash "$here/build-paraview-plugin.sh"
ctest --test-dir build-paraview/build --output-on-failure
