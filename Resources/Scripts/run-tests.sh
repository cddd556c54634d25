#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The project's test command (README, CI): install dependencies, build, run every test.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/../.."
bash "$here/install-dependencies.sh"
bash "$here/build.sh"
ctest --test-dir build --output-on-failure -j2
