#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Install dependencies, build, mesh the bundled example into out/ and draw it.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/../.."
bash "$here/install-dependencies.sh"
bash "$here/build.sh"
mkdir -p out
build/bin/labelmesher mesh Resources/Data/totalseg_example_seg.nrrd -o out/example.vtu --report out/example.json
/usr/bin/python3 Resources/Scripts/mesh_picture.py out/example.vtu out/example.png --bound 15
echo "Wrote out/example.vtu (open it in ParaView or 3D Slicer), out/example.json and out/example.png"
