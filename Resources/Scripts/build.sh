#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Configures and builds LabelMesher in ./build (Ninja, at most 2 parallel jobs
# unless LABELMESHER_JOBS says otherwise). Run from anywhere. Extra arguments go to CMake.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/../.."
source "$here/ccache.sh"
cmake -S . -B build -G Ninja -DPython3_EXECUTABLE=/usr/bin/python3 "${labelmesher_ccache[@]}" "$@"
cmake --build build -j "${LABELMESHER_JOBS:-2}"
