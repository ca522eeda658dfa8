#!/usr/bin/env python3
"""Merge the drivers' timing files into <results>/timings.csv and print the table.

Every driver writes <results>/<target>/timing_<driver>.csv (a split target's run jobs into their folders
<results>/.runs/<target>/<run>/): target, driver, wall_s, particle_steps, threads: the wall time of its run and the
particle-steps its time loops took. Every particle-step is taken by the process that reports it: a run job steps its
run, and the run that collects it reads it from its folder and steps none (issue 45; records of older versions carry
a reused_particle_steps column, the steps a store of runs served instead: not read). This script collects them,
sorted by wall time, adds the particle-steps per second, writes <results>/timings.csv and prints it with the totals,
and the critical path: the drivers' time with one node for every job (make figures LAUNCH=slurm on enough nodes;
issue 17), the longest chain of a target's runs (side by side, so their longest) and then its own driver
invocations (one after another).
"""
import argparse
import csv
import glob
import os
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--results", default="results")
    args = ap.parse_args()
    rows = []
    # The targets' driver runs, and the simulation runs of split targets (<results>/.runs/T/<run>/, Makefile
    # run_rules), labelled T/<run>.
    paths = [(p, None) for p in sorted(glob.glob(os.path.join(args.results, "*", "timing_*.csv")))]
    paths += [(p, os.path.basename(os.path.dirname(p)))
              for p in sorted(glob.glob(os.path.join(args.results, ".runs", "*", "*", "timing_*.csv")))]
    for path, run in paths:
        with open(path) as f:
            for r in csv.DictReader(l for l in f if not l.startswith("#")):
                if run:
                    r["target"] = f"{r['target']}/{run}"
                rows.append(r)
    if not rows:
        print(f"timings: no timing files under {args.results}")
        return 0
    rows.sort(key=lambda r: -float(r["wall_s"]))
    out = os.path.join(args.results, "timings.csv")
    cols = ["target", "driver", "wall_s", "particle_steps", "particle_steps_per_s", "threads"]
    total = steps_total = 0.0
    with open(out + ".part", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(cols)
        for r in rows:
            wall, ps = float(r["wall_s"]), float(r["particle_steps"])
            total += wall
            steps_total += ps
            w.writerow([r["target"], r["driver"], f"{wall:.3f}", f"{ps:.0f}", f"{ps / wall:.4g}" if wall > 0 else "",
                        r["threads"]])
    os.replace(out + ".part", out)  # whole or not at all (issue 47): a killed run leaves the previous file
    print(f"{'target':10} {'driver':48} {'wall_s':>9} {'particle-steps':>15} {'per s':>10} threads")
    for r in rows:
        wall, ps = float(r["wall_s"]), float(r["particle_steps"])
        rate = f"{ps / wall:.3g}" if wall > 0 and ps > 0 else "-"
        print(f"{r['target']:10} {r['driver']:48} {wall:9.1f} {ps:15.4g} {rate:>10} {r['threads']:>7}")
    print(f"timings: {len(rows)} driver runs, {total:.0f} s in the drivers, {steps_total:.4g} particle-steps -> {out}")
    target, seconds = critical_path(rows)
    print(f"timings: critical path {seconds:.0f} s ({target}): the drivers' time with a node for every job")
    return 0


def critical_path(rows):
    """(target, seconds) of the longest chain of jobs: a target's runs (labelled T/<run>) run side by side before
    its own driver invocations, which run one after another (the Makefile's run_rules and target_rules)."""
    runs, own = {}, {}
    for r in rows:
        target, _, run = r["target"].partition("/")
        wall = float(r["wall_s"])
        if run:
            runs[target] = max(runs.get(target, 0.0), wall)
        else:
            own[target] = own.get(target, 0.0) + wall
    chains = {t: runs.get(t, 0.0) + own.get(t, 0.0) for t in set(runs) | set(own)}
    target = max(chains, key=lambda t: (chains[t], t))
    return target, chains[target]


if __name__ == "__main__":
    sys.exit(main())
