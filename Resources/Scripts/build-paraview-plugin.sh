#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Builds the LabelMesher ParaView plugin in ./build-paraview against ParaView
# 5.11's own VTK. Debian's paraview-dev cannot be installed beside libvtk9-dev
# (python3-paraview conflicts with python3-vtk9), so ParaView's packages are
# downloaded and unpacked into build-paraview/prefix (no root needed for that);
# the few -dev packages ParaView's CMake config looks for are installed
# normally. Result: build-paraview/build/lib/paraview-5.11/plugins/LabelMesher/LabelMesher.so
# and the ctest tests of Plugins/ParaView/Testing (label paraview).
set -euo pipefail
cd "$(dirname "$0")/../.."
root="$PWD/build-paraview"
prefix="$root/prefix"

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo="sudo"
fi
# ParaView's CMake config looks for the -dev ones; the GUI test runs the client
# (Qt OpenGL and Help) under xvfb-run.
needed=(libx11-dev libgl-dev libglew-dev libdouble-conversion-dev libfreetype-dev libhdf5-dev
        libxml2-dev libnetcdf-dev libqt5opengl5 libqt5help5 xvfb xauth libgl1-mesa-dri)
missing=()
for p in "${needed[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "build-paraview-plugin: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update
  $sudo apt-get install -y --no-install-recommends "${missing[@]}"
fi

if [ ! -x "$prefix/usr/bin/pvbatch" ]; then
  mkdir -p "$root/debs"
  (cd "$root/debs" && { apt-get download paraview paraview-dev python3-paraview 2>/dev/null ||
    { $sudo apt-get update && apt-get download paraview paraview-dev python3-paraview; }; })
  for deb in "$root"/debs/*.deb; do
    dpkg-deb -x "$deb" "$prefix"
  done
fi
# ParaView's own runtime libraries come with the VTK/Qt set; say so plainly if one is missing.
if ldd "$prefix/usr/bin/pvbatch" | grep -q "not found"; then
  echo "build-paraview-plugin: pvbatch lacks libraries:" >&2
  ldd "$prefix/usr/bin/pvbatch" | grep "not found" >&2
  exit 1
fi

cmake -S Plugins/ParaView -B "$root/build" -G Ninja \
  -DParaView_DIR="$prefix/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11" \
  -DPVBATCH="$prefix/usr/bin/pvbatch" \
  -DPARAVIEW_PYTHONPATH="$prefix/usr/lib/python3/dist-packages" "$@"
cmake --build "$root/build" -j "${LABELMESHER_JOBS:-2}"
