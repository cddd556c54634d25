#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Installs the Debian 12 packages needed to build and test LabelMesher.
# Idempotent: when every package is already installed it does nothing (no apt).
# Needs root (or sudo) only when something is missing.
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config
  ccache                               # every build directory compiles through it (ccache.sh)
  libvtk9-dev python3-vtk9            # VTK 9.1 + its Python wrapping (filters, I/O, module system)
  libinsighttoolkit5-dev libgdcm-tools # ITK 5.2 image readers (NRRD, NIfTI, MetaImage); gdcm tools silence ITK's config
  libeigen3-dev
  zlib1g-dev                           # the CLI's PNG structure check
  qtbase5-dev libvtk9-qt-dev          # Qt5 widgets and the desktop viewer (QVTKOpenGLNativeWidget)
  libp4est-dev mpi-default-dev        # the octree (p4est 2.2, GPL-2.0-or-later) and the MPI it is built against
  mpi-default-bin                      # mpirun: the CLI shared out over several processes (Testing/CLI/mpi_test.py)
  libgtest-dev libbenchmark-dev       # C++ tests and benchmarks
  libcgal-dev                          # baseline comparisons in the benchmarks
  clang libclang-rt-14-dev             # the libFuzzer targets (run-fuzzers.sh)
  afl++                                # the readers' fuzz targets (run-reader-fuzzers.sh: ITK needs GCC)
  python3-numpy                        # Python tests
  xvfb xauth libgl1-mesa-dri           # offscreen pictures (mesh_picture.py): Debian's VTK renders through GLX only
  python3-meshio gmsh                  # independent readers of the mesh files in the tests (meshio, gmsh -check)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-dependencies: all ${#packages[@]} packages already installed"
  exit 0
fi

echo "install-dependencies: installing ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update
$sudo apt-get install -y --no-install-recommends "${packages[@]}"
