#!/usr/bin/env python3
"""A split target through the Makefile's own rules (run_rules: a run job per run into results/.runs/T/<run>/, then the
target's driver with --runs-from) gives the files the same driver gives when it steps every run itself (T_RUN_DRIVER=
on the command line), value for value (tools/compare_results.py: bit for bit, wall times aside): no field of a run is
lost on its way through the run job's folder. Quick runs of TARGETS (default G-tab1, a plate row and its trace,
and H-72, the 72 hexagon runs: ~8 s of CPU in all). Then the collecting run again, from a folder whose run job did
not complete: refused, naming the file.
Usage: test_run_jobs.py --build BUILD_DIR [--targets T ...] (ctest passes the build; the drivers must be built)."""
import argparse
import glob
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "experiments"))
import targets  # noqa: E402


def make(build, results, goals, *overrides):
    # A make of its own, not a sub-make of the `make test` that runs ctest (whose jobserver it cannot reach).
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL", "MAKEOVERRIDES")}
    env["OMP_NUM_THREADS"] = "1"
    return subprocess.run(["make", "-s", "-C", ROOT, f"BUILD={build}", f"RESULTS={results}", "DRIVER_FLAGS=--quick",
                           *overrides] + [f"{results}/{g}/.done" for g in goals],
                          env=env, capture_output=True, text=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--targets", nargs="+", default=["G-tab1", "H-72"])
    args = ap.parse_args()
    build = os.path.abspath(args.build)
    declared = {t.name: t for t in targets.read().targets}
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        split, whole = os.path.join(tmp, "split"), os.path.join(tmp, "whole")
        out = make(build, split, args.targets)
        if out.returncode != 0:
            failures.append(f"the split make failed:\n{out.stdout}{out.stderr}")
        out = make(build, whole, args.targets, *[f"{t}_RUN_DRIVER=" for t in args.targets])
        if out.returncode != 0:
            failures.append(f"the whole make failed:\n{out.stdout}{out.stderr}")
        for t in args.targets:
            jobs = glob.glob(os.path.join(split, ".runs", t, "*", "timing_*.csv"))
            if not jobs:
                failures.append(f"{t}: no run job ran")
            if os.path.exists(os.path.join(whole, ".runs", t)):
                failures.append(f"{t}: run jobs ran although T_RUN_DRIVER was empty")
            cmp = subprocess.run([sys.executable, os.path.join(ROOT, "tools", "compare_results.py"),
                                  os.path.join(whole, t), os.path.join(split, t)], capture_output=True, text=True)
            print(f"{t}: {len(jobs)} run jobs; {cmp.stdout.strip().splitlines()[-1] if cmp.stdout else cmp.stderr}")
            if cmp.returncode != 0:
                failures.append(f"{t}: the collected files differ from the stepped ones:\n{cmp.stdout}")
            if not jobs:
                continue
            # A run job interrupted: its completion record gone. The collecting run refuses the folder, by name.
            record = sorted(jobs)[0]
            os.remove(record)
            driver = os.path.basename(record)[len("timing_"):-len(".csv")]
            ran = subprocess.run([os.path.join(build, "bin", driver), "--quick", "--out", os.path.join(tmp, "again"),
                                  "--runs-from", os.path.join(split, ".runs", t)] + declared[t].args.split(),
                                 capture_output=True, text=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
            if ran.returncode == 0 or record not in ran.stderr:
                failures.append(f"{t}: a run folder without its completion record was not refused by name: "
                                f"exit {ran.returncode}, {ran.stderr.strip()}")
    for f in failures:
        print("FAIL:", f)
    print(f"test_run_jobs: {'FAIL' if failures else 'ok'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
