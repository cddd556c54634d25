# SPDX-License-Identifier: GPL-2.0-or-later
# Sourced by the fuzz scripts: runs shell functions in the background, at most N at a time.
#   pool_run N FUNCTION ARGS...   starts FUNCTION ARGS... once fewer than N are running
#   pool_wait                     waits for all; pool_status is 1 if any of them failed
pool_pids=()
pool_status=0
pool_run() {
  local limit="$1"; shift
  while [ "$(jobs -rp | wc -l)" -ge "$limit" ]; do
    wait -n || true
  done
  "$@" &
  pool_pids+=("$!")
}
pool_wait() {
  local pid
  for pid in "${pool_pids[@]}"; do
    wait "$pid" || pool_status=1
  done
}
