#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Builds labelmesher_compare_cgal and compares LabelMesher (mesher then
# decimator, h = 2, 15 degrees) with CGAL 5.5 Mesh_3 on a Cassini volume and the
# shared real label volumes, then prints one table of ratios ours/CGAL. See
# Benchmarks/README.md.
#
#   Benchmarks/compare_with_cgal.sh [BUILD_DIR] [-- extra options for the tool]
#
# Environment: CASSINI_N (default 100), DATA_DIR (default <repo>/../shared/data),
# JOBS (default 2), SKIP_BUILD=1 to use an existing build, LARGE=1 for the large
# volumes too (digimouse, torso, frog, liver).
set -eu

here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/.." && pwd)
build=${1:-$repo/build-bench}
[ $# -gt 0 ] && shift
[ "${1:-}" = "--" ] && shift
data=${DATA_DIR:-$repo/../shared/data}
n=${CASSINI_N:-100}
jobs=${JOBS:-2}

if [ "${SKIP_BUILD:-0}" != 1 ]; then
  if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$repo" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DLABELMESHER_BUILD_BENCHMARKS=ON
  fi
  cmake --build "$build" -j "$jobs" --target labelmesher_compare_cgal
fi
tool=$build/bin/labelmesher_compare_cgal
[ -x "$tool" ] || { echo "error: $tool not built (is CGAL installed? libcgal-dev)" >&2; exit 1; }

logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
run() { # name, tool arguments...
  name=$1
  shift
  echo "=== $name ==="
  if "$tool" --name "$name" "$@" > "$logs/$name.log" 2>&1; then
    cat "$logs/$name.log"
  else
    cat "$logs/$name.log"
    echo "SUMMARY $name FAILED" >> "$logs/$name.log"
  fi
  echo
}

run "cassini$n" --cassini "$n" "$@"
run iso2mesh_rat_head "$data/3d/iso2mesh_rat_head.nrrd" "$@"
run totalseg_example_seg "$data/3d/totalseg_example_seg.nrrd" "$@"
if [ "${LARGE:-0}" = 1 ]; then # the large volumes: minutes each
  for volume in digimouse torso_label frog liver; do
    run "$volume" "$data/3d/$volume.nrrd" "$@"
  done
fi

echo "=== ratios ours/CGAL (time, tetrahedra, min dihedral, h(I,M), h(M,I), peak memory); topology = labels matching the image ==="
cat "$logs"/*.log | awk '
  function r(a, b) { return (b == 0) ? ((a == 0) ? "1" : "inf") : sprintf("%.3f", a / b) }
  BEGIN {
    printf "%-22s %9s %9s %9s %9s %9s %9s   %-11s %-11s\n", "input", "time", "tets", "minDih", "h(I,M)", "h(M,I)", "memory", "topo ours", "topo CGAL"
  }
  $1 == "SUMMARY" && $3 == "FAILED" { printf "%-22s failed (see log above)\n", $2; next }
  $1 == "SUMMARY" {
    printf "%-22s %9s %9s %9s %9s %9s %9s   %-11s %-11s\n", $2, r($3, $4), r($5, $6), r($7, $8), r($9, $10), r($11, $12), r($15, $16), $13, $14
  }'
echo
echo "=== misclassified voxels (same check for both; quadratic: with -- --order 2) ==="
cat "$logs"/*.log | awk '
  function r(a, b) { return (b == 0) ? ((a == 0) ? "1" : "inf") : sprintf("%.3f", a / b) }
  BEGIN { printf "%-22s %12s %12s %12s %9s %12s %9s\n", "input", "voxels", "ours", "CGAL", "ours/CGAL", "quadratic", "quad/CGAL" }
  $1 == "ACCURACY" {
    q = ($6 < 0) ? "-" : $6
    qr = ($6 < 0) ? "-" : r($6, $5)
    printf "%-22s %12s %12s %12s %9s %12s %9s\n", $2, $3, $4, $5, r($4, $5), q, qr
  }'
