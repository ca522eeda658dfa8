#!/usr/bin/env python3
"""make bench-peer: PySPH's solid_mech/rings.py and LAMMPS MACHDYN's smd/ulsph against our rings, same steps, same cores.

1. PySPH (Debian python3-pysph), with --openmp and OMP_NUM_THREADS=<threads>, output disabled, into a
   temporary directory: a short warm-up run first (the first run compiles its Cython kernels into
   ~/.pysph/source; later runs load them), then the timed run of --steps steps. Its integrator is the one of
   ElasticSolidsScheme, EPECIntegrator (evaluate-predict-evaluate-correct: two force evaluations per step,
   like our predictor-corrector); the script reads the integrator and the particle count from PySPH's log.
   Time: the stepping only, as PySPH reports it: "Run took" (Solver.solve) minus the one extra force
   evaluation Solver.solve makes before the first step (Integrator.initial_acceleration in its
   profile_info.csv); the setup, kernel loading and Python start-up are not counted.
2. Ours, right after: build/bin/bench_gray_scenes --scenes rings --steps <steps> --max-threads <threads>
   (the rings at dp = 0.05, PySPH's layout; its time excludes 5 warm-up steps and the setup). It also runs
   the 1-thread case; the row taken is the one with <threads> threads.
2b. LAMMPS MACHDYN (smd/ulsph with its artificial stress 0.3, Hertz contact between the rings; a plugin of Debian's
   lmp, tools/peers/build_machdyn.sh) on our rings at the same spacing (build/bin/peer_rings --action layout --dp 0.05,
   experiments/peers/lammps_rings.py --no-frames), on <threads> MPI ranks (Debian's liblammps is an Open MPI build;
   it has no OpenMP styles for MACHDYN), for --steps steps; its time is LAMMPS's "Loop time" (the stepping). Its
   integrator is velocity Verlet: one force evaluation per step, against two of ours and PySPH's EPEC; the speeds
   are therefore also compared per force evaluation (particle-steps/s x evaluations per step).
3. Writes <out>/peer.csv with the columns of results/bench.csv: one row for PySPH (variant
   pysph_<version>_openmp), one for ours (variant ours_artstress+xsph+visc) and the ratio row, variant
   ratio_ours_over_pysph, whose particle_steps_per_s column holds the ratio of the two throughputs
   (dimensionless; particles and wall_s are nan there); and for LAMMPS a row (variant lammps_<version>_mpi<threads>)
   and two ratio rows, ratio_ours_over_lammps (per step) and ratio_ours_over_lammps_per_force_eval. The '#' header records the commands, the commit and
   the load average before the runs (the machine may be shared: a busy machine slows both, not equally).
4. Merges the rows into results/bench.csv: creates it if absent; if present with the same header, replaces
   any earlier bench-peer rows with these (so a rerun does not pile up rows); a different header is an error.
Prints the table and the ratio.
"""
import argparse
import csv
import datetime
import io
import os
import re
import subprocess
import sys
import tempfile

COLUMNS = ["scene", "variant", "particles", "steps", "threads", "wall_s", "particle_steps_per_s", "error_name", "error"]
SCENE = "rings_pysph_layout"
RATIO_VARIANT = "ratio_ours_over_pysph"
LAMMPS_RATIO_VARIANTS = ("ratio_ours_over_lammps", "ratio_ours_over_lammps_per_force_eval")
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OURS_VARIANT = "ours_artstress+xsph+visc"


def fail(msg):
    print(f"bench_peer: {msg}", file=sys.stderr)
    sys.exit(1)


def run(cmd, env, cwd=None):
    print("bench_peer: " + " ".join(cmd), flush=True)
    p = subprocess.run(cmd, env=env, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode != 0:
        sys.stdout.write(p.stdout[-4000:])
        fail(f"command failed with exit code {p.returncode}: {' '.join(cmd)}")
    return p.stdout


def pysph_command(python, example, steps, outdir):
    return [python, example, "--openmp", "--max-steps", str(steps), "--disable-output", "--pfreq", "1000000000",
            "-d", outdir]


def run_pysph(python, example, steps, warmup_steps, env, tmp):
    run(pysph_command(python, example, warmup_steps, os.path.join(tmp, "pysph_warmup")), env)
    outdir = os.path.join(tmp, "pysph")
    text = run(pysph_command(python, example, steps, outdir), env)
    log = ""
    for name in os.listdir(outdir):
        if name.endswith(".log"):
            with open(os.path.join(outdir, name)) as f:
                log += f.read()
    both = text + "\n" + log
    m = re.search(r"Run took:\s*([0-9.eE+-]+)\s*secs", both)
    if not m:
        fail("PySPH printed no 'Run took' line")
    run_s = float(m.group(1))
    m = re.search(r"No of particles:\s*\n\s*\w+:\s*(\d+)", both) or re.search(r"with (\d+) particles", both)
    if not m:
        fail("PySPH printed no particle count")
    particles = int(m.group(1))
    m = re.search(r"Using integrator:\s*\n-+\s*\n\s*(\S.*)", both)
    integrator = m.group(1).strip() if m else "unknown"
    initial_s = 0.0
    prof = os.path.join(outdir, "profile_info.csv")
    if os.path.exists(prof):
        with open(prof) as f:
            for r in csv.DictReader(f):
                if r.get("function") == "Integrator.initial_acceleration":
                    initial_s += float(r["time"])
    else:
        print("bench_peer: no profile_info.csv from PySPH: its time includes the initial force evaluation")
    return {"particles": particles, "wall_s": run_s - initial_s, "run_took_s": run_s, "initial_s": initial_s,
            "integrator": integrator}


def run_ours(binary, steps, threads, env, tmp):
    outdir = os.path.join(tmp, "ours")
    run([binary, "--scenes", "rings", "--steps", str(steps), "--max-threads", str(threads), "--out", outdir], env)
    with open(os.path.join(outdir, "bench_gray_scenes.csv")) as f:
        rows = [r for r in csv.DictReader(l for l in f if not l.startswith("#"))]
    for r in rows:
        if r["scene"] == SCENE and int(r["threads"]) == threads:
            return r
    fail(f"bench_gray_scenes wrote no {SCENE} row with {threads} threads")


def run_lammps(bin_dir, steps, ranks, env, tmp):
    """LAMMPS MACHDYN smd/ulsph on our rings at dp = 0.05 (the layout of ours and PySPH's example): (particles,
    wall_s of its stepping, version)."""
    layout = os.path.join(tmp, "lammps_layout")
    run([os.path.join(bin_dir, "peer_rings"), "--action", "layout", "--dp", "0.05", "--gap", "0.2", "--eps", "0.3",
         "--out", layout], env)
    frames = os.path.join(tmp, "lammps_frames.csv")
    run(["/usr/bin/python3", os.path.join(ROOT, "experiments", "peers", "lammps_rings.py"), "--layout", layout,
         "--frames", frames, "--work", os.path.join(tmp, "lammps"), "--art-stress", "0.3", "--max-steps", str(steps),
         "--no-frames", "--ranks", str(ranks)], env)
    meta = {}
    with open(frames + ".run") as f:
        for line in f:
            k, _, v = line[1:].partition("=")
            meta[k.strip()] = v.strip()
    if int(meta["steps"]) != steps:
        fail(f"LAMMPS ran {meta['steps']} steps, not {steps}")
    return int(meta["particles"]), float(meta["wall_s"]), meta.get("code_version", "unknown")


def read_table(path):
    """Header line and data rows of a CSV whose comment lines start with '#'."""
    with open(path) as f:
        lines = [l for l in f if not l.startswith("#")]
    if not lines:
        return None, []
    return lines[0].strip().split(","), list(csv.DictReader(io.StringIO("".join(lines))))


def is_peer_row(r):
    return r["scene"] == SCENE and (r["variant"].startswith(("pysph_", "lammps_")) or
                                    r["variant"] in (OURS_VARIANT, RATIO_VARIANT) + LAMMPS_RATIO_VARIANTS)


def write_rows(f, rows):
    w = csv.DictWriter(f, fieldnames=COLUMNS, lineterminator="\n")
    w.writeheader()
    w.writerows(rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--steps", type=int, default=600, help="timed steps for both codes")
    ap.add_argument("--threads", type=int, default=2, help="OMP_NUM_THREADS for both codes")
    ap.add_argument("--warmup-steps", type=int, default=2, help="steps of PySPH's warm-up (compile) run")
    ap.add_argument("--ours", default="build/bin/bench_gray_scenes")
    ap.add_argument("--lammps", action=argparse.BooleanOptionalAction, default=True,
                    help="also LAMMPS MACHDYN (needs tools/peers/build_machdyn.sh and build/bin/peer_rings)")
    ap.add_argument("--pysph-python", default="/usr/bin/python3")
    ap.add_argument("--pysph-example", default=None, help="default: pysph/examples/solid_mech/rings.py")
    ap.add_argument("--out", default="results/bench", help="directory of peer.csv")
    ap.add_argument("--bench-csv", default="results/bench.csv")
    args = ap.parse_args()

    example = args.pysph_example
    if example is None:
        import pysph
        example = os.path.join(os.path.dirname(pysph.__file__), "examples", "solid_mech", "rings.py")
        version = pysph.__version__
    else:
        version = "unknown"
    if not os.path.exists(example):
        fail(f"no PySPH example {example} (apt-get install python3-pysph)")
    if not os.access(args.ours, os.X_OK):
        fail(f"no executable {args.ours} (cmake --build build --target bench_gray_scenes)")

    env = dict(os.environ, OMP_NUM_THREADS=str(args.threads))
    with open("/proc/loadavg") as f:
        load = f.read().split()[0]
    if float(load) > 0.5:
        print(f"bench_peer: warning: load average {load} before the runs: the machine is busy, the timings too")
    commit = subprocess.run(["git", "describe", "--always", "--dirty", "--abbrev=12"], stdout=subprocess.PIPE,
                            stderr=subprocess.DEVNULL, text=True).stdout.strip() or "unknown"
    with tempfile.TemporaryDirectory(prefix="bench_peer_") as tmp:
        py = run_pysph(args.pysph_python, example, args.steps, args.warmup_steps, env, tmp)
        ours = run_ours(args.ours, args.steps, args.threads, env, tmp)
        if args.lammps:
            lmp_particles, lmp_wall, lmp_version = run_lammps(os.path.dirname(args.ours), args.steps, args.threads,
                                                              dict(env, OMP_NUM_THREADS="1"), tmp)

    py_rate = py["particles"] * args.steps / py["wall_s"]
    ours_rate = float(ours["particle_steps_per_s"])
    ratio = ours_rate / py_rate
    rows = [
        {"scene": SCENE, "variant": f"pysph_{version}_openmp", "particles": py["particles"], "steps": args.steps,
         "threads": args.threads, "wall_s": f"{py['wall_s']:.6g}", "particle_steps_per_s": f"{py_rate:.6g}",
         "error_name": "none", "error": "nan"},
        {"scene": SCENE, "variant": OURS_VARIANT, "particles": ours["particles"], "steps": ours["steps"],
         "threads": ours["threads"], "wall_s": f"{float(ours['wall_s']):.6g}",
         "particle_steps_per_s": f"{ours_rate:.6g}",
         "error_name": "none", "error": "nan"},
        {"scene": SCENE, "variant": RATIO_VARIANT, "particles": "nan", "steps": args.steps, "threads": args.threads,
         "wall_s": "nan", "particle_steps_per_s": f"{ratio:.4g}", "error_name": "none", "error": "nan"},
    ]

    if args.lammps:
        lmp_rate = lmp_particles * args.steps / lmp_wall
        rows += [
            {"scene": SCENE, "variant": f"lammps_{lmp_version}_mpi{args.threads}", "particles": lmp_particles,
             "steps": args.steps, "threads": args.threads, "wall_s": f"{lmp_wall:.6g}",
             "particle_steps_per_s": f"{lmp_rate:.6g}", "error_name": "none", "error": "nan"},
            {"scene": SCENE, "variant": LAMMPS_RATIO_VARIANTS[0], "particles": "nan", "steps": args.steps,
             "threads": args.threads, "wall_s": "nan", "particle_steps_per_s": f"{ours_rate / lmp_rate:.4g}",
             "error_name": "none", "error": "nan"},
            {"scene": SCENE, "variant": LAMMPS_RATIO_VARIANTS[1], "particles": "nan", "steps": args.steps,
             "threads": args.threads, "wall_s": "nan", "particle_steps_per_s": f"{2 * ours_rate / lmp_rate:.4g}",
             "error_name": "none", "error": "nan"},
        ]
    os.makedirs(args.out, exist_ok=True)
    peer = os.path.join(args.out, "peer.csv")
    with open(peer, "w") as f:
        f.write("# driver = tools/bench_peer.py\n# target = bench-peer\n")
        f.write(f"# code_version = {commit}\n")
        f.write(f"# date = {datetime.datetime.now(datetime.timezone.utc).strftime('%Y-%m-%dT%H:%M:%SZ')}\n")
        f.write(f"# pysph = {' '.join(pysph_command(args.pysph_python, example, args.steps, 'TMP'))}"
                f" (after a {args.warmup_steps}-step warm-up run)\n")
        f.write(f"# pysph_integrator = {py['integrator']}\n")
        f.write(f"# pysph_time = Run took {py['run_took_s']:.6g} s minus initial_acceleration "
                f"{py['initial_s']:.6g} s\n")
        f.write(f"# ours = {args.ours} --scenes rings --steps {args.steps} --max-threads {args.threads}\n")
        f.write(f"# OMP_NUM_THREADS = {args.threads}\n# load_average_before = {load}\n")
        f.write(f"# ratio row: particle_steps_per_s = ours / pysph (both two force evaluations per step)\n")
        if args.lammps:
            f.write(f"# lammps = peer_rings --action layout --dp 0.05 --gap 0.2 --eps 0.3; lammps_rings.py --art-stress 0.3 "
                    f"--max-steps {args.steps} --no-frames --ranks {args.threads}; time: its Loop time\n")
            f.write("# lammps ratio rows: ours / lammps per step, and per force evaluation (ours 2 a step, LAMMPS 1)\n")
        write_rows(f, rows)

    kept = []
    if os.path.exists(args.bench_csv):
        header, old = read_table(args.bench_csv)
        if header is not None and header != COLUMNS:
            fail(f"{args.bench_csv} has the header {','.join(header)}, not {','.join(COLUMNS)}: not merged "
                 f"(the rows are in {peer})")
        kept = [r for r in old if not is_peer_row(r)]
    with open(args.bench_csv, "w") as f:
        write_rows(f, kept + rows)

    print(f"bench_peer: {peer}, merged into {args.bench_csv}")
    widths = [max(len(c), *(len(str(r[c])) for r in rows)) for c in COLUMNS]
    for line in [dict(zip(COLUMNS, COLUMNS))] + rows:
        print("  ".join(str(line[c]).ljust(w) for c, w in zip(COLUMNS, widths)))
    print(f"bench_peer: PySPH integrator {py['integrator']}, {py['particles']} particles; ours {ours['particles']}")
    print(f"bench_peer: ours / PySPH = {ratio:.3g} ({ours_rate:.3g} / {py_rate:.3g} particle-steps/s, "
          f"{args.steps} steps, {args.threads} threads)")
    if args.lammps:
        print(f"bench_peer: ours / LAMMPS = {ours_rate / lmp_rate:.3g} per step, {2 * ours_rate / lmp_rate:.3g} per force "
              f"evaluation ({lmp_rate:.3g} particle-steps/s on {args.threads} MPI ranks, {lmp_particles} particles)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
