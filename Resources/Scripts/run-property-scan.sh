#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The long property scan (issue 17): labelmesher_property_scan over 130,000 seeded random images,
# 2D and 3D, the three generators (smooth, boxes, thin features), every distance bound the seeds
# draw (0..3 voxels each way), through the mesher alone, the decimator and (2D) the curver, in
# chunks that resume after an interruption.
#
#   run-property-scan.sh STATE_DIR [SCAN_BINARY]
#
# Each finished chunk leaves STATE_DIR/<chunk>.log (written under a temporary name, renamed when the
# chunk ends), so running the same command again skips the finished chunks and redoes at most the
# one that was cut. At the end it prints the totals and every failing seed, and exits 1 if any.
# SCAN_BINARY defaults to build/bin/labelmesher_property_scan; copy it elsewhere first if the build
# tree will be rebuilt while the scan runs. One core; nice it to keep the machine usable.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
state="${1:?usage: run-property-scan.sh STATE_DIR [SCAN_BINARY]}"
scan="${2:-$here/../../build/bin/labelmesher_property_scan}"
[ -x "$scan" ] || { echo "run-property-scan: no scan program at $scan (build first)" >&2; exit 2; }
mkdir -p "$state"

# mode family dimension images chunk — seeds start at 1,000,000, beyond the CI suites' seeds.
plan=(
  "mesh     smooth 2 15000 1000"
  "mesh     boxes  2 15000 1000"
  "decimate smooth 2 15000 1000"
  "decimate boxes  2 15000 1000"
  "curve    smooth 2  5000  500"
  "curve    boxes  2  5000  500"
  "mesh     boxes  3 10000  250"
  "mesh     smooth 3  5000  250"
  "decimate boxes  3 10000  250"
  "decimate smooth 3  5000  250"
  "mesh     thin   2 10000 1000"
  "decimate thin   2 10000 1000"
  "mesh     thin   3  5000  250"
  "decimate thin   3  5000  250"
)
first_seed=1000000

for entry in "${plan[@]}"; do
  read -r mode family dimension images chunk <<<"$entry"
  flag=""
  [ "$mode" = mesh ] || flag="--$mode"
  for ((start = first_seed; start < first_seed + images; start += chunk)); do
    name="$mode-$family-${dimension}d-$start"
    [ -f "$state/$name.log" ] && continue
    status=0
    "$scan" $flag "$family" "$dimension" "$start" "$chunk" >"$state/$name.part" 2>&1 || status=$?
    if [ "$status" -gt 1 ]; then
      echo "run-property-scan: $name stopped with status $status (see $state/$name.part)" >&2
      exit "$status"
    fi
    mv "$state/$name.part" "$state/$name.log"
    echo "$(date -u +%H:%M:%S) $name: $(grep -E 'images violate' "$state/$name.log")"
  done
done

echo "--- totals ($state)"
awk '/images violate a guarantee/ {
       split($0, a, ": "); split(a[2], b, " ");
       bad += b[1]; all += b[3];
       key = $1 " " $2 " " $3; if ($1 == "decimated" || $1 == "curved") key = $1 " " $2 " " $3; else key = "mesher " $1 " " $2;
       n[key] += b[3]; f[key] += b[1] }
     END { for (k in n) printf "%-24s %8d images, %d failing\n", k, n[k], f[k];
           printf "%-24s %8d images, %d failing\n", "all", all, bad }' "$state"/*.log | sort
grep -h "FAILS" "$state"/*.log || true
! grep -q "FAILS" "$state"/*.log
