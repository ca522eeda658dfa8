#!/usr/bin/env bash
# Runs every driver of two versions of the code and compares what they write, file by file:
#   tools/compare_commits.sh [--full] [--rel R] A B
# A and B are git revisions of this repository (checked out into $WORK/<rev>) or paths to existing
# checkouts (built in place, e.g. . for the working tree). Each is built (CMake, Release) and every driver
# of experiments/targets.mk is run in --quick mode, one thread each, two at a time (as make test does);
# with --full, the full-resolution runs named below are added: the first row of each plate table, the
# rings and the hexagon. Then tools/compare_results.py compares the two result trees (bit for bit unless
# --rel is given) and its exit code is this script's.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
WORK=${WORK:-/tmp/compare}
full=0
rel=0
while [ $# -gt 2 ]; do
  case "$1" in
    --full) full=1; shift ;;
    --rel) rel=$2; shift 2 ;;
    *) echo "usage: $0 [--full] [--rel R] A B" >&2; exit 2 ;;
  esac
done
[ $# -eq 2 ] || { echo "usage: $0 [--full] [--rel R] A B" >&2; exit 2; }
jobs=$(nproc 2>/dev/null || echo 2)

checkout() {  # a revision or a directory -> the directory of a checkout
  if [ -d "$1" ]; then (cd "$1" && pwd); return; fi
  local rev dir
  rev=$(git -C "$here" rev-parse --short=12 "$1")
  dir="$WORK/$rev"
  if [ ! -d "$dir" ]; then
    git clone -q "$here" "$dir"
    git -C "$dir" checkout -q "$rev"
  fi
  echo "$dir"
}

run_side() {  # checkout, result directory
  local dir=$1 out=$2
  echo "== $dir -> $out" >&2
  (cd "$dir" && cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null && cmake --build build -j "$jobs" > /dev/null)
  rm -rf "$out"
  mkdir -p "$out"
  (cd "$dir" && OMP_NUM_THREADS=1 make --no-print-directory -s -j "$jobs" results RESULTS="$out/quick" DRIVER_FLAGS=--quick > "$out/quick.log" 2>&1) \
    || { echo "quick runs failed in $dir (see $out/quick.log)" >&2; exit 1; }
  if [ "$full" = 1 ]; then
    local bin="$dir/build/bin"
    "$bin/gray2001_table1_2_plate_periods" --table 1 --rows H2_Vf0.001_mu0.22 --out "$out/full/G-tab1" > /dev/null 2>&1
    "$bin/gray2001_table1_2_plate_periods" --table 2 --rows H1_Vf0.01_mu0.22 --out "$out/full/G-tab2" > /dev/null 2>&1
    "$bin/gray2001_fig6_7_rings" --out "$out/full/G-fig6" > /dev/null 2>&1
    "$bin/hoover2004_fig4_hexagon_md_spam" --out "$out/full/H-fig4" > /dev/null 2>&1
  fi
}

a=$(checkout "$1")
b=$(checkout "$2")
run_side "$a" "$WORK/results-A"
run_side "$b" "$WORK/results-B"
exec "$here/tools/compare_results.py" --rel "$rel" "$WORK/results-A" "$WORK/results-B"
