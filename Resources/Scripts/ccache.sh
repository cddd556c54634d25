# SPDX-License-Identifier: GPL-2.0-or-later
# Sourced by the build scripts: when Debian's ccache is installed, every build directory (build,
# build-sanitize, build-fuzz, build-afl, build-paraview) compiles through it, so that a rebuild
# after a clean clone, or a second build of the same sources with the same flags, re-uses the
# objects that did not change. Sets the array labelmesher_ccache (CMake arguments, maybe empty).
# The cache lives in ccache's default place (~/.cache/ccache); CCACHE_DIR moves it.
labelmesher_ccache=()
if command -v ccache >/dev/null 2>&1; then
  labelmesher_ccache=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  # Sources are hashed by content, not by path: a fresh clone in another folder hits the cache.
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
  export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-true}"
fi
