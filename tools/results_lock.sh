#!/usr/bin/env bash
# One pipeline at a time per results folder (issue 47 item 2): runs CMD while holding an exclusive lock on
# DIR/.lock, or refuses at once, naming the holder, when another pipeline holds it.
#   tools/results_lock.sh DIR WHAT CMD...     (WHAT: how the holder is named, e.g. "make figures")
# The lock is flock(1)'s: the kernel releases it when the last process holding it ends, however it ends (a
# SIGKILL, a power cut), so a lock cannot go stale; DIR/.lock.info says who holds it (pid, what, when). An info
# file left by a holder that ended without removing it is taken over, with a line saying so. Children inherit
# the lock: a sub-make still running after its parent was killed keeps the folder locked until it ends.
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: $0 DIR WHAT CMD..." >&2; exit 2; }
dir=$1 what=$2
shift 2
mkdir -p "$dir"
lock="$dir/.lock"
exec 9>>"$lock"
if ! flock -n 9; then
  echo "$what: refused: $dir is in use by $(cat "$lock.info" 2>/dev/null || echo 'another pipeline'); wait for it to end, or give this one another RESULTS=" >&2
  exit 1
fi
if [ -s "$lock.info" ]; then
  echo "$what: taking over the lock of $dir from $(cat "$lock.info"), which ended without releasing it" >&2
fi
echo "pid $$ ($what, started $(date '+%Y-%m-%d %H:%M:%S'))" > "$lock.info"
trap 'rm -f "$lock.info"' EXIT
"$@"
