#!/usr/bin/env python3
"""Compare two result trees written by the drivers, file by file and cell by cell.

  tools/compare_results.py A B [--rel 1e-12]

Every CSV under A is matched with the file of the same relative path under B. The header lines that
describe the run rather than its result (# date, # code_version, and the description) are ignored; every
other line must agree: text cells exactly, numeric cells within the relative tolerance (default 0: bit for
bit, as the drivers print shortest round-trip numbers). Timings are not results and are skipped: the columns
wall_s, build_s, *_wall_s and particle_steps_per_s, and the rows of a values file whose quantity names one,
and the drivers' timing_*.csv files (and timings.csv). Hidden folders are not compared: results/.runs holds the run
jobs' folders, whose files the collecting runs read into the targets' folders (which are compared), and a tree
of a version without run jobs has none. Prints one line per file that differs (with the
largest relative difference and where), the files present on one side only, and a summary; exits 1 if any
file differs or is missing. Used to show that a refactor or a speed-up changes no result
(tools/compare_commits.sh runs the drivers of two commits and calls this).
"""
import argparse
import math
import re
import os
import sys

IGNORED_META = ("# date =", "# code_version =", "# description =")
TIMING = re.compile(r"(^|_)(wall|build)_s$|per_s$")


def csv_files(root):
    out = set()
    for d, dirs, files in os.walk(root):
        dirs[:] = [x for x in dirs if not x.startswith(".")]
        for f in files:
            if f.endswith(".csv") and not f.startswith("timing"):
                out.add(os.path.relpath(os.path.join(d, f), root))
    return out


def number(s):
    try:
        return float(s)
    except ValueError:
        return None


def split(line):
    # Quoted cells (notes) are compared as text: a plain split keeps the quotes on both sides alike.
    return line.rstrip("\n").split(",")


def compare_file(a, b, rel):
    with open(a) as fa, open(b) as fb:
        la = [l for l in fa if not l.startswith(IGNORED_META)]
        lb = [l for l in fb if not l.startswith(IGNORED_META)]
    if len(la) != len(lb):
        return f"{len(la)} lines against {len(lb)}", math.inf
    header = next((split(l) for l in la if not l.startswith("#")), [])
    timing_cols = {j for j, c in enumerate(header) if TIMING.search(c.strip('"'))}
    values_file = header[:2] == ["quantity", "value"]
    worst, where = 0.0, ""
    for i, (x, y) in enumerate(zip(la, lb)):
        if x == y:
            continue
        cx, cy = split(x), split(y)
        if len(cx) != len(cy):
            return f"line {i + 1}: {len(cx)} cells against {len(cy)}", math.inf
        if values_file and cx[0] == cy[0] and TIMING.search(cx[0]):
            continue
        for j, (u, v) in enumerate(zip(cx, cy)):
            if u == v or j in timing_cols:
                continue
            nu, nv = number(u), number(v)
            if nu is None or nv is None:
                return f"line {i + 1} cell {j + 1}: '{u}' against '{v}'", math.inf
            if math.isnan(nu) and math.isnan(nv):
                continue
            d = abs(nu - nv) / max(abs(nu), abs(nv), 1e-300)
            if d > worst:
                worst, where = d, f"line {i + 1} cell {j + 1}: {u} against {v}"
    if worst > rel:
        return where, worst
    return None, worst


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--rel", type=float, default=0.0, help="largest accepted relative difference of a number")
    args = ap.parse_args()
    fa, fb = csv_files(args.a), csv_files(args.b)
    bad = 0
    for f in sorted(fa - fb):
        print(f"only in {args.a}: {f}")
        bad += 1
    for f in sorted(fb - fa):
        print(f"only in {args.b}: {f}")
        bad += 1
    same = within = 0
    for f in sorted(fa & fb):
        msg, worst = compare_file(os.path.join(args.a, f), os.path.join(args.b, f), args.rel)
        if msg is not None:
            print(f"DIFFERS {f}: {msg} (largest relative difference {worst:.3g})")
            bad += 1
        elif worst > 0:
            print(f"within {args.rel:g}: {f} (largest relative difference {worst:.3g})")
            within += 1
        else:
            same += 1
    print(f"compare_results: {len(fa & fb)} files in both: {same} identical, {within} within {args.rel:g}, "
          f"{bad} differing or missing")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
