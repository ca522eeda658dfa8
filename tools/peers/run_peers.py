#!/usr/bin/env python3
"""make peers: independent codes on our scenes, measured with our measurement code (issue 44).

Every scene is a module tools/peers/scene_<name>.py (SCENES below, in this order) with
  NAME                      the scene's name: its runs go to <out>/<NAME>/, its tables to <out>/<NAME>.csv
  RUN_COLUMNS               the columns of <out>/<NAME>.csv: one row per run (case, code): the code, its version,
                            every setting, resolution, particles, steps, wall time, particle-steps/s, force
                            evaluations per step and the measured quantities
  cases(quick) -> [case]    the cases it runs; with quick a smoke run of every code path (a few steps, coarse)
  case_name(case) -> str    a folder name
  run_case(ctx, case) -> [row]   runs the peers (and ours) of one case; a peer starts from our layout (our
                            tool build/bin/peer_<scene> --action layout) and its trace is measured by our
                            functions (--action measure)
  compare(rows) -> [row]    the rows of compare.csv (COMPARE_COLUMNS) from all its runs rows
  missing(case, rows)       (optional) the variants of a done case that its runs.csv lacks: the case runs again
A case is done when <out>/<NAME>/<case>/runs.csv exists (written last): a rerun of make peers skips it and reads
that file (--force reruns it), so an interrupted make peers resumes; --cases runs only the cases it names, and the
tables hold every case that is done. Writes <out>/<NAME>.csv per scene run and
<out>/compare.csv (every scene present in <out>: published | ours | peer | theory with the differences, and the
speed per force evaluation).
Usage: run_peers.py --build BUILD --out DIR [--quick] [--threads N] [--scenes a,b] [--cases SUBSTRING[$]] [--force]
"""
import argparse
import csv
import importlib
import math
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "experiments", "peers"))
sys.dont_write_bytecode = True
import peer_io  # noqa: E402

PY = "/usr/bin/python3"
SCENES = ["plate", "rings", "slab", "tl"]
COMPARE_COLUMNS = ["scene", "case", "quantity", "dp", "published", "theory", "ours", "code", "variant", "peer",
                   "peer_over_ours", "ours_over_theory", "peer_over_theory", "ours_particle_steps_per_s",
                   "peer_particle_steps_per_s", "ours_force_evals_per_step", "peer_force_evals_per_step",
                   "ours_over_peer_per_force_eval", "ours_version", "peer_version", "note"]


def fail(msg):
    print(f"run_peers: {msg}", file=sys.stderr)
    sys.exit(1)


def num(x):
    """A number of a runs row (typed when just run, text when read back from runs.csv); nan if empty."""
    try:
        return float(x)
    except (TypeError, ValueError):
        return math.nan


def ratio(a, b):
    a, b = num(a), num(b)
    return a / b - 1 if math.isfinite(a) and math.isfinite(b) and b != 0 else math.nan


class Context:
    """What a scene module needs from the run: paths, mode, threads, and a logged way to run a command."""

    def __init__(self, args):
        self.build, self.out, self.quick, self.threads = args.build, args.out, args.quick, args.threads
        self.force = args.force
        self.root, self.py = ROOT, PY
        self.env = dict(os.environ, OMP_NUM_THREADS=str(args.threads))

    def bin(self, name):
        return os.path.join(self.build, "bin", name)

    def run(self, cmd, log, env=None):
        print("run_peers: " + " ".join(cmd), flush=True)
        t0 = time.time()
        with open(log, "w") as f:
            p = subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT, env=env or self.env)
        if p.returncode != 0:
            with open(log) as f:
                sys.stderr.write(f.read()[-3000:])
            fail(f"exit code {p.returncode}: {' '.join(cmd)} (log {log})")
        return time.time() - t0

    def version(self, code):
        if code == "pysph":
            out = subprocess.run([PY, "-c", "import pysph; print(pysph.__version__)"], capture_output=True, text=True)
            return out.stdout.strip() or "unknown"
        if code == "lammps":
            out = subprocess.run(["dpkg-query", "-W", "-f", "${Version}", "lammps"], capture_output=True, text=True)
            return out.stdout.strip() or "unknown"
        return "unknown"


def write(path, rows, columns, what):
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as f:
        f.write(f"# {what}, written by tools/peers/run_peers.py on {time.strftime('%Y-%m-%d %H:%M:%S')}\n")
        w = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow(r)
    os.replace(tmp, path)


def run_scene(ctx, mod, args):
    rows = []
    for case in mod.cases(ctx.quick):
        name = mod.case_name(case)
        d = os.path.join(ctx.out, mod.NAME, name)
        done = os.path.join(d, "runs.csv")
        selected = not args.cases or (name == args.cases[:-1] if args.cases.endswith("$") else args.cases in name)
        if os.path.exists(done) and not (args.force and selected):
            prior = peer_io.read_table(done)
            todo = mod.missing(case, prior) if hasattr(mod, "missing") else []
            if not (todo and selected):
                print(f"run_peers: {mod.NAME}/{name} done before (its runs.csv; --force reruns it)")
                rows += prior
                continue
            print(f"run_peers: {mod.NAME}/{name}: its runs.csv lacks {', '.join(todo)}: run again (a scene may keep "
                  "the runs that finished)")
        if not selected:  # not run now; the tables hold the cases that are done
            continue
        os.makedirs(d, exist_ok=True)
        case_rows = mod.run_case(ctx, case, d)
        write(done, case_rows, mod.RUN_COLUMNS, f"peers, {mod.NAME}, case {name}")
        rows += case_rows
    write(os.path.join(ctx.out, f"{mod.NAME}.csv"), rows, mod.RUN_COLUMNS, f"peers, {mod.NAME}: every run")
    write(os.path.join(ctx.out, f"{mod.NAME}_compare.csv"), mod.compare(rows), COMPARE_COLUMNS,
          f"peers, {mod.NAME}: ours against each peer")
    print(f"run_peers: {mod.NAME}: {len(rows)} runs")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--quick", action="store_true", help="a smoke run of every code path (measures nothing)")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--scenes", default=",".join(SCENES), help="comma-separated, of " + ",".join(SCENES))
    ap.add_argument("--cases", default="", help="only the cases whose folder name contains this (ending in $: is this)")
    ap.add_argument("--force", action="store_true", help="rerun cases that are done")
    args = ap.parse_args()
    wanted = [s for s in args.scenes.split(",") if s]
    for s in wanted:
        if s not in SCENES:
            fail(f"--scenes: unknown scene '{s}' (known: {', '.join(SCENES)})")
    if args.threads < 1:
        fail("--threads must be >= 1")
    sys.path.insert(0, HERE)
    ctx = Context(args)
    os.makedirs(ctx.out, exist_ok=True)
    for s in wanted:
        if not os.path.exists(os.path.join(HERE, f"scene_{s}.py")):
            print(f"run_peers: no tools/peers/scene_{s}.py yet: scene {s} skipped")
            continue
        run_scene(ctx, importlib.import_module(f"scene_{s}"), args)
    compare = []
    for s in SCENES:
        p = os.path.join(ctx.out, f"{s}_compare.csv")
        if os.path.exists(p):
            compare += peer_io.read_table(p)
    write(os.path.join(ctx.out, "compare.csv"), compare, COMPARE_COLUMNS, "peers: ours against each peer, every scene")
    print(f"run_peers: {os.path.join(ctx.out, 'compare.csv')} ({len(compare)} rows)")
    write_values(ctx.out, compare)


def check_name(r):
    """The quantity a reference row of kind peer names: <code>_<variant>_over_ours_<quantity>_dp<dp>."""
    return f"{r['code']}_{r['variant']}_over_ours_{r['quantity']}_dp{num(r['dp']):g}"


def write_values(out, compare):
    """<out>/values_peers.csv (quantity,value,ours_code_version,note): peer / ours - 1 of every compare row, the
    values that reference rows of expect = peer check (reference/check.py)."""
    path = os.path.join(out, "values_peers.csv")
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as f:
        peer_io.write_header(f, {"written_by": "tools/peers/run_peers.py", "date": time.strftime("%Y-%m-%d %H:%M:%S")})
        w = csv.writer(f)
        w.writerow(["quantity", "value", "ours_code_version", "note"])
        for r in compare:
            w.writerow([check_name(r), r["peer_over_ours"], r.get("ours_version", ""),
                        f"{r['code']} {r.get('peer_version', '')} ({r['variant']}) / ours - 1, {r['scene']} case {r['case']}"])
    os.replace(tmp, path)


if __name__ == "__main__":
    main()
