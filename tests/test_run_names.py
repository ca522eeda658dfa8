#!/usr/bin/env python3
"""The runs a split target declares (T_RUNS in experiments/targets.mk: jobs of their own, Makefile run_rules) are
exactly the runs its driver plans at full resolution (the driver's --list-runs true), so that no declared job
steps nothing and no run of the study is left to the collecting driver. Targets whose run driver has no
--list-runs (G-tab1, G-tab2: their --rows are checked by the driver's own one_of) are skipped by name, listed below."""
import argparse
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "experiments"))
import targets  # noqa: E402

WITHOUT_LIST = {"G-tab1", "G-tab2"}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    args = ap.parse_args()
    bad = checked = 0
    for t in targets.read().targets:
        if not t.runs or t.name in WITHOUT_LIST:
            continue
        driver = os.path.join(args.build, "bin", t.run_driver or t.drivers[0])
        with tempfile.TemporaryDirectory() as tmp:
            out = subprocess.run([driver, "--list-runs", "true", "--out", tmp] + t.args.split(), capture_output=True,
                                 text=True, check=True).stdout.split()
        checked += 1
        if sorted(out) != sorted(t.runs):
            bad += 1
            print(f"{t.name}: declared {sorted(set(t.runs) - set(out))} not planned, planned {sorted(set(out) - set(t.runs))} "
                  "not declared")
        else:
            print(f"{t.name}: {len(out)} runs declared and planned")
    print(f"test_run_names: {checked} targets checked, {bad} differ")
    return 1 if bad or not checked else 0


if __name__ == "__main__":
    sys.exit(main())
