#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Configures and builds LabelMesher in ./build (Ninja, at most 2 parallel jobs
# unless LABELMESHER_JOBS says otherwise). Run from anywhere.
set -euo pipefail
cd "$(dirname "$0")/../.."
cmake -S . -B build -G Ninja -DPython3_EXECUTABLE=/usr/bin/python3 "$@"
cmake --build build -j "${LABELMESHER_JOBS:-2}"
