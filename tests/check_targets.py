#!/usr/bin/env python3
"""Check that everything keyed by a target id follows the one declaration, experiments/targets.mk.

For every target T declared there (TARGETS += T):
  reference/T.csv exists and its rows all name T;  plots/T.py exists;  paper/targets.csv has one row for T;
  every driver of T_DRIVERS has exactly one source experiments/<folder>/<driver>.cpp.
Every BENCH_DRIVERS entry has its source too. And nothing extra: no reference/*.csv, plots/*.py (other than
the shared lowercase modules such as plotstyle.py), paper/targets.csv row or driver source that no
declaration names. Make's reading of the declaration (`make -s list-targets`) must agree with the Python
reader's (experiments/targets.py), unless make is not installed.

Prints one line per problem and exits 1 if there is any; run by `make test` (first) and by ctest.
"""
import argparse
import difflib
import glob
import os
import re
import shutil
import subprocess
import sys

import pandas as pd

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(ROOT, "experiments"))
import targets as declaration  # noqa: E402  (experiments/targets.py)

# Folders of experiments/ that hold no drivers (CMakeLists.txt builds every other experiments/<folder>/*.cpp).
NOT_DRIVER_FOLDERS = {"frame", "peers"}  # peers: make peers' tool and PySPH scripts (CMakeLists.txt)


def make_reading(root):
    """Make's own reading of targets.mk, as [(target, drivers, args)] and the bench drivers; None without make."""
    make = shutil.which("make")
    if make is None:
        return None
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL", "MAKEOVERRIDES")}
    out = subprocess.run([make, "-s", "--no-print-directory", "-C", root, "list-targets"], env=env,
                         capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(f"make -s list-targets failed: {out.stderr.strip()}")
    rows = [line.split(";") for line in out.stdout.splitlines()]
    bench = [r for r in rows if r[0] == "BENCH_DRIVERS"]
    rows = [(r[0], r[1].split(), r[2].strip()) for r in rows if r[0] != "BENCH_DRIVERS"]
    return rows, bench[0][1].split() if bench else []


def as_lines(reading):
    """A reading as the lines of `make -s list-targets`."""
    rows, bench = reading
    return [f"{t};{' '.join(d)};{a}" for t, d, a in rows] + [f"BENCH_DRIVERS;{' '.join(bench)};"]


def problems(root):
    rel = lambda p: os.path.relpath(p, root)  # noqa: E731
    try:
        decl = declaration.read(os.path.join(root, "experiments", "targets.mk"))
    except declaration.DeclarationError as e:
        return [str(e)], None
    found = []
    declared = set(decl.names)

    try:
        made = make_reading(root)
    except RuntimeError as e:
        found.append(str(e))
        made = None
    if made is not None:
        # Make's $(strip) also collapses inner blanks, which the shell's splitting of the arguments ignores.
        ours = ([(t.name, t.drivers, " ".join(t.args.split())) for t in decl.targets], decl.bench_drivers)
        if made != ours:
            diff = [d for d in difflib.unified_diff(as_lines(ours), as_lines(made), lineterm="", n=0)
                    if d[:1] in "+-" and d[:3] not in ("+++", "---")]
            found.append("experiments/targets.mk: Make (make -s list-targets, +) and experiments/targets.py (-) "
                         "read it differently: " + " | ".join(diff))

    # Reference files: one per declared target, rows naming their own target.
    for t in decl.names:
        path = os.path.join(root, "reference", f"{t}.csv")
        if not os.path.exists(path):
            found.append(f"{t}: reference/{t}.csv missing")
            continue
        ref = pd.read_csv(path, comment="#", dtype=str, keep_default_na=False, skipinitialspace=True)
        if "target" not in ref.columns:
            found.append(f"{t}: reference/{t}.csv has no target column")
        elif set(ref.target) - {t}:
            found.append(f"{t}: reference/{t}.csv has rows for {sorted(set(ref.target) - {t})}")
    for path in sorted(glob.glob(os.path.join(root, "reference", "*.csv"))):
        t = os.path.basename(path)[:-len(".csv")]
        if t not in declared:
            found.append(f"{rel(path)}: {t} is not a target declared in experiments/targets.mk")

    # Plots: one per declared target; other scripts must be shared modules (lowercase names).
    for t in decl.names:
        if not os.path.exists(os.path.join(root, "plots", f"{t}.py")):
            found.append(f"{t}: plots/{t}.py missing")
    for path in sorted(glob.glob(os.path.join(root, "plots", "*.py"))):
        t = os.path.basename(path)[:-len(".py")]
        if t not in declared and not re.fullmatch(r"[a-z_][a-z0-9_]*", t):
            found.append(f"{rel(path)}: {t} is not a target declared in experiments/targets.mk "
                         "(shared plot modules have lowercase names)")

    # The report's descriptions: one row per declared target.
    rows = pd.read_csv(os.path.join(root, "paper", "targets.csv"), dtype=str, keep_default_na=False)
    counts = rows.target.value_counts()
    for t in decl.names:
        if t not in counts:
            found.append(f"{t}: paper/targets.csv has no row")
    for t, n in counts.items():
        if t not in declared:
            found.append(f"paper/targets.csv: row for {t}, which is not declared in experiments/targets.mk")
        elif n > 1:
            found.append(f"paper/targets.csv: {n} rows for {t}")

    # Driver sources: experiments/<folder>/<driver>.cpp, each named by a declaration.
    sources = {}
    for path in sorted(glob.glob(os.path.join(root, "experiments", "*", "*.cpp"))):
        if os.path.basename(os.path.dirname(path)) not in NOT_DRIVER_FOLDERS:
            sources.setdefault(os.path.basename(path)[:-len(".cpp")], []).append(rel(path))
    named = {}
    for t in decl.targets:
        for d in t.drivers:
            named.setdefault(d, t.name)
    for d in decl.bench_drivers:
        named.setdefault(d, "BENCH_DRIVERS")
    for d, by in named.items():
        if d not in sources:
            found.append(f"{by}: driver {d} has no source experiments/*/{d}.cpp")
        elif len(sources[d]) > 1:
            found.append(f"{by}: driver {d} has several sources {sources[d]}")
    for d, paths in sources.items():
        if d not in named:
            found.append(f"{paths[0]}: driver {d} is built but named by no T_DRIVERS or BENCH_DRIVERS "
                         "in experiments/targets.mk")
    return found, decl


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--root", default=ROOT, help="the source tree (default: the one holding this script)")
    args = ap.parse_args()
    found, decl = problems(os.path.abspath(args.root))
    for p in found:
        print(f"check_targets: {p}")
    if found:
        print(f"check_targets: {len(found)} problem(s) with the declaration experiments/targets.mk")
        return 1
    print(f"check_targets: {len(decl.targets)} targets and {len(decl.bench_drivers)} bench drivers declared in "
          "experiments/targets.mk; reference, plot, report row and driver sources consistent")
    return 0


if __name__ == "__main__":
    sys.exit(main())
