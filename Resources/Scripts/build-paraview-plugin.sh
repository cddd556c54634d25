#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Builds the LabelMesher ParaView plugin in ./build-paraview against ParaView
# 5.11's own VTK. Debian's paraview-dev cannot be installed beside libvtk9-dev
# (python3-paraview conflicts with python3-vtk9), so ParaView's packages are
# downloaded and unpacked into a private prefix (no root needed for that);
# the few -dev packages ParaView's CMake config looks for are installed
# normally. Result: build-paraview/build/lib/paraview-5.11/plugins/LabelMesher/LabelMesher.so
# and the ctest tests of Plugins/ParaView/Testing (label paraview).
# The unpacked packages are kept outside the clone, in
# ${XDG_CACHE_HOME:-~/.cache}/labelmesher/paraview-<version>, so that another clone on the same
# machine neither downloads nor unpacks them again; the build is configured once (later runs only
# rebuild what changed; arguments given to this script configure it again) and compiles through
# ccache.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/../.."
root="$PWD/build-paraview"

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

version=$(apt-cache policy paraview 2>/dev/null | sed -n 's/^ *Candidate: *//p')
if [ -z "$version" ] || [ "$version" = "(none)" ]; then
  $sudo apt-get update
  version=$(apt-cache policy paraview | sed -n 's/^ *Candidate: *//p')
fi
prefix="${XDG_CACHE_HOME:-$HOME/.cache}/labelmesher/paraview-${version//[^A-Za-z0-9.+-]/_}"
if [ ! -x "$prefix/usr/bin/pvbatch" ]; then
  # Unpacked beside the final place and renamed when complete: an interrupted run leaves no
  # half-unpacked prefix behind that a later run would take for a whole one.
  partial="$prefix.partial"
  rm -rf "$partial"
  mkdir -p "$partial/debs"
  (cd "$partial/debs" && apt-get download paraview paraview-dev python3-paraview)
  for deb in "$partial"/debs/*.deb; do
    dpkg-deb -x "$deb" "$partial"
  done
  rm -rf "$partial/debs"
  mv "$partial" "$prefix"
fi
# ParaView's own runtime libraries come with the VTK/Qt set; say so plainly if one is missing.
if ldd "$prefix/usr/bin/pvbatch" | grep -q "not found"; then
  echo "build-paraview-plugin: pvbatch lacks libraries:" >&2
  ldd "$prefix/usr/bin/pvbatch" | grep "not found" >&2
  exit 1
fi

source "$here/ccache.sh"
if [ ! -f "$root/build/CMakeCache.txt" ] || [ $# -gt 0 ] ||
   ! grep -q "^PVBATCH:FILEPATH=$prefix/usr/bin/pvbatch\$" "$root/build/CMakeCache.txt"; then
  cmake -S Plugins/ParaView -B "$root/build" -G Ninja \
    -DParaView_DIR="$prefix/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11" \
    -DPVBATCH="$prefix/usr/bin/pvbatch" \
    -DPARAVIEW_PYTHONPATH="$prefix/usr/lib/python3/dist-packages" "${labelmesher_ccache[@]}" "$@"
fi
cmake --build "$root/build" -j "${LABELMESHER_JOBS:-2}"
