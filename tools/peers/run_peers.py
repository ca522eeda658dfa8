#!/usr/bin/env python3
"""make peers: independent codes on our scenes, measured with our measurement code (issue 44).

For every case of PLATE_CASES (QUICK_CASES with --quick: row, thickness, V_f, mu, spacing, the peer's clamp):
  1. build/bin/peer_scenes --action layout writes our particles and settings into <out>/<case>/layout/;
  2. the peer runs them (PySPH: experiments/peers/pysph_plate.py) and leaves its trace in <out>/<case>/;
  3. peer_scenes --action measure measures that trace with the functions our drivers use;
  4. ours runs the same row at the same spacing with its own driver (gray2001_table1_2_plate_periods).
Writes <out>/plate.csv: one row per (case, code) with the peer, its version, every setting, the measured
quantities, wall time, particle-steps/s and force evaluations per step, and ours beside it; then
<out>/compare.csv, ours | peer | theory with the differences. --quick: a smoke run of every code (a few steps,
coarse), which measures nothing but runs the whole path.
Usage: run_peers.py --build BUILD --out DIR [--quick] [--threads N]
"""
import argparse
import csv
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PY = "/usr/bin/python3"

# The plate rows of Gray 2001 Table 1 (H = 2) and Table 2 (H = 1) that the peers run, at spacings the peer
# reaches in minutes: n = H / dp particles across the thickness (the paper's is n = 20 for Table 1).
PLATE_CASES = [
    # (row, H, Vf, mu, dp, clamp of the peer)
    ("H2_Vf0.01_mu0.6", 2.0, 0.01, 0.6, 0.2, "ours"),
    ("H2_Vf0.01_mu0.6", 2.0, 0.01, 0.6, 0.2, "walls"),
    ("H2_Vf0.01_mu0.22", 2.0, 0.01, 0.22, 0.2, "ours"),
    ("H2_Vf0.01_mu0.3", 2.0, 0.01, 0.3, 0.2, "ours"),
]
QUICK_CASES = [("H2_Vf0.01_mu0.6", 2.0, 0.01, 0.6, 0.5, "ours")]
QUICK_STEPS = 30
OURS_DONE = set()  # our runs of this invocation: a row and spacing that two peer settings share runs once


def fail(msg):
    print(f"run_peers: {msg}", file=sys.stderr)
    sys.exit(1)


def run(cmd, log, env=None):
    print("run_peers: " + " ".join(cmd), flush=True)
    with open(log, "w") as f:
        p = subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT, env=env)
    if p.returncode != 0:
        with open(log) as f:
            sys.stderr.write(f.read()[-3000:])
        fail(f"exit code {p.returncode}: {' '.join(cmd)} (log {log})")


def values(path):
    with open(path) as f:
        return {r["quantity"]: float(r["value"]) for r in csv.DictReader(l for l in f if not l.startswith("#"))}


def header(path):
    meta = {}
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                break
            k, _, v = line[1:].partition("=")
            meta[k.strip()] = v.strip()
    return meta


def pysph_version():
    out = subprocess.run([PY, "-c", "import pysph; print(pysph.__version__)"], capture_output=True, text=True)
    return out.stdout.strip() or "unknown"


def plate_case(args, case, env):
    row, H, Vf, mu, dp, clamp = case
    name = f"plate_{row}_dp{dp}_{clamp}"
    d = os.path.join(args.out, name)
    layout = os.path.join(d, "layout")
    os.makedirs(layout, exist_ok=True)
    bin_ = lambda b: os.path.join(args.build, "bin", b)
    common = ["--scene", "plate", "--dp", str(dp), "--H", str(H), "--Vf", str(Vf), "--mu", str(mu)]
    run([bin_("peer_scenes"), "--action", "layout", "--out", layout] + common, os.path.join(d, "layout.log"), env)
    settings = {k: float(v) for k, v in (r.split(",", 1) for r in open(os.path.join(layout, "settings.csv"))
                                         if not r.startswith("#") and not r.startswith("name,"))}
    trace = os.path.join(d, "trace_pysph.csv")
    cmd = [PY, os.path.join(ROOT, "experiments", "peers", "pysph_plate.py"), "--layout", layout, "--trace", trace,
           "--clamp", clamp, "--disable-output", "-d", os.path.join(d, "pysph_out")]
    if args.threads > 1:
        cmd.append("--openmp")
    if args.quick:
        cmd += ["--max-steps", str(QUICK_STEPS)]
    run(cmd, os.path.join(d, "pysph.log"), env)
    measured = os.path.join(d, "measured_pysph")
    os.makedirs(measured, exist_ok=True)
    run([bin_("peer_scenes"), "--action", "measure", "--trace", trace, "--out", measured] + common,
        os.path.join(d, "measure.log"), env)
    peer = values(os.path.join(measured, "values_peer_scenes.csv"))
    meta = header(trace)
    rows = [dict(case=name, code="pysph", version=pysph_version(), clamp=clamp, row=row, H=H, Vf=Vf, mu=mu, dp=dp,
                 particles=int(meta["particles"]), dt=settings["dt"], steps=int(meta["steps"]),
                 wall_s=float(meta["wall_s"]), force_evals_per_step=2, T_sph=peer["T_sph"],
                 crossings=int(peer["crossings"]), tip_amplitude=peer["tip_amplitude"])]
    # Ours, the same row at the same spacing, by its own driver (only once per row and spacing: the clamp is ours).
    ours_dir = os.path.join(args.out, f"plate_{row}_dp{dp}_ours_code")
    if ours_dir not in OURS_DONE:
        OURS_DONE.add(ours_dir)
        os.makedirs(ours_dir, exist_ok=True)
        cmd = [bin_("gray2001_table1_2_plate_periods"), "--dp", str(dp), "--table", "1" if H == 2.0 else "2",
               "--rows", row, "--coarse-reference", "false", "--same-n-reading", "false", "--out", ours_dir]
        if args.quick:
            cmd += ["--max-steps", str(QUICK_STEPS)]
        run(cmd, os.path.join(ours_dir, "run.log"), env)
    with open(os.path.join(ours_dir, "periods.csv")) as f:
        p = next(csv.DictReader(l for l in f if not l.startswith("#")))
    ours_T = float(p["T_sph"]) if not args.quick else float("nan")
    rows.append(dict(case=name, code="ours", version=header(os.path.join(ours_dir, "periods.csv")).get("code_version", ""),
                     clamp="ours", row=row, H=H, Vf=Vf, mu=mu, dp=dp, particles=int(float(p["particles"])),
                     dt=float(p["dt"]), steps=int(float(p["steps"])), wall_s=float(p["wall_s"]), force_evals_per_step=2,
                     T_sph=ours_T, crossings=float("nan"), tip_amplitude=float(p["tip_amplitude"])))
    for r in rows:
        r["particle_steps_per_s"] = r["particles"] * r["steps"] / r["wall_s"] if r["wall_s"] > 0 else float("nan")
        r["T_theory_reading"] = float(p["T_theory_reading"])
    return rows


def write(path, rows, columns):
    with open(path, "w", newline="") as f:
        f.write(f"# written by tools/peers/run_peers.py on {time.strftime('%Y-%m-%d %H:%M:%S')}\n")
        w = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow(r)
    print(f"run_peers: {path} ({len(rows)} rows)")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--threads", type=int, default=1)
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    env = dict(os.environ, OMP_NUM_THREADS=str(args.threads))
    plate = []
    for case in QUICK_CASES if args.quick else PLATE_CASES:
        plate += plate_case(args, case, env)
    cols = ["case", "code", "version", "clamp", "row", "H", "Vf", "mu", "dp", "particles", "dt", "steps", "wall_s",
            "particle_steps_per_s", "force_evals_per_step", "T_sph", "crossings", "tip_amplitude", "T_theory_reading"]
    write(os.path.join(args.out, "plate.csv"), plate, cols)
    compare = []
    ours = {(r["row"], r["dp"]): r for r in plate if r["code"] == "ours"}
    for r in plate:
        if r["code"] == "ours":
            continue
        o = ours[(r["row"], r["dp"])]
        compare.append(dict(scene="plate", quantity=f"T_sph_{r['row']}", dp=r["dp"], peer=r["code"], peer_setting=f"clamp={r['clamp']}",
                            ours=o["T_sph"], peer_value=r["T_sph"], theory=r["T_theory_reading"],
                            peer_over_ours=r["T_sph"] / o["T_sph"] - 1, ours_over_theory=o["T_sph"] / r["T_theory_reading"] - 1,
                            peer_over_theory=r["T_sph"] / r["T_theory_reading"] - 1,
                            speed_ratio_ours_over_peer=o["particle_steps_per_s"] / r["particle_steps_per_s"]))
    write(os.path.join(args.out, "compare.csv"), compare,
          ["scene", "quantity", "dp", "peer", "peer_setting", "ours", "peer_value", "theory", "peer_over_ours",
           "ours_over_theory", "peer_over_theory", "speed_ratio_ours_over_peer"])


if __name__ == "__main__":
    main()
