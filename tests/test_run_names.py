#!/usr/bin/env python3
"""The run jobs of the split targets (experiments/targets.mk T_RUN_DRIVER; Makefile run_rules) are the runs their
drivers plan, at full resolution and in --quick mode:
  - every declared run driver prints its runs (--list-runs true, with the target's arguments), at least one, each
    name once, each usable as a folder and a Make target ([A-Za-z0-9_.-], not starting with '.');
  - Make's lists (make -s list-runs, from the run lists it generates from the drivers) are exactly those;
  - every driver that offers --list-runs is some target's T_RUN_DRIVER (a driver with runs is split where it runs).
Usage: test_run_names.py --build BUILD_DIR (ctest passes it; the drivers must have been built there)."""
import argparse
import glob
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "experiments"))
import targets  # noqa: E402

NAME = re.compile(r"[A-Za-z0-9_-][A-Za-z0-9_.-]*")


def planned(build, t, flags):
    driver = os.path.join(build, "bin", t.run_driver)
    with tempfile.TemporaryDirectory() as tmp:
        return subprocess.run([driver, "--list-runs", "true", "--out", tmp] + t.args.split() + flags,
                              capture_output=True, text=True, check=True).stdout.split()


def make_lists(build, flags):
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL", "MAKEOVERRIDES")}
    with tempfile.TemporaryDirectory() as results:
        out = subprocess.run(["make", "-s", "-C", ROOT, f"BUILD={build}", f"RESULTS={results}",
                              f"DRIVER_FLAGS={' '.join(flags)}", "list-runs"],
                             capture_output=True, text=True, check=True, env=env).stdout
    return {line.split(";")[0]: line.split(";")[1].split() for line in out.splitlines() if ";" in line}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    args = ap.parse_args()
    build = os.path.abspath(args.build)
    declared = [t for t in targets.read().targets if t.run_driver]
    bad = 0
    for flags in ([], ["--quick"]):
        mode = " ".join(flags) or "full"
        lists = make_lists(build, flags)
        for t in declared:
            runs = planned(build, t, flags)
            problems = []
            if not runs:
                problems.append("no runs")
            if len(set(runs)) != len(runs):
                problems.append(f"names given twice: {sorted({r for r in runs if runs.count(r) > 1})}")
            problems += [f"'{r}' is not a folder and Make target name" for r in runs if not NAME.fullmatch(r)]
            if lists.get(t.name) != runs:
                problems.append(f"Make's list {lists.get(t.name)} is not the driver's {runs}")
            print(f"{t.name} ({mode}): {len(runs)} runs" + (": " + "; ".join(problems) if problems else ""))
            bad += bool(problems)
        extra = sorted(set(lists) - {t.name for t in declared})
        if extra:
            print(f"Make lists runs of undeclared targets ({mode}): {extra}")
            bad += 1
    run_drivers = {t.run_driver for t in declared}
    for source in sorted(glob.glob(os.path.join(ROOT, "experiments", "*", "*.cpp"))):  # the drivers (not peers)
        name = os.path.splitext(os.path.basename(source))[0]
        path = os.path.join(build, "bin", name)
        if "/peers/" in source or not os.path.exists(path):
            continue
        helped = subprocess.run([path, "--help"], capture_output=True, text=True)
        if "--list-runs" in helped.stdout and name not in run_drivers:
            print(f"{name} offers --list-runs, but no target declares it as its T_RUN_DRIVER")
            bad += 1
    print(f"test_run_names: {len(declared)} split targets checked, {bad} problems")
    return 1 if bad or not declared else 0


if __name__ == "__main__":
    sys.exit(main())
