#!/usr/bin/env python3
"""make studies (issue 46 item 2): the paper's unstated choices, one run job each, and a sensitivity table per study.

A study varies one choice the paper does not state at a time, everything else at make figures' settings, and
writes every open row's value under each choice beside the published number. It is outside make figures (the
main job does not grow); a reading a row adopts from it must then run in make figures.

  studies.py --bin build/bin --out results/studies [--jobs 2] [--studies plate] [--variants a,b] [--list]

Each job is one driver run into <out>/<study>/<variant>/<row>/, as make figures runs it (its completion record
last): a job whose record is there is not run again, so an interrupted make studies resumes. The table,
<out>/<study>_sensitivity.csv, has per row and choice the value, its difference from the published number and
whether it lies within the row's tolerance; a choice whose jobs have not all run is left out, said on stderr.
"""
import argparse
import concurrent.futures
import csv
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "experiments", "peers"))
from peer_io import read_table  # noqa: E402  (a CSV with '#' comment lines, as dicts)

PLATE_DRIVER = "gray2001_table1_2_plate_periods"
# Every row of Tables 1 and 2: a choice that reproduces an open row must also keep the others (the second
# published numbers it was not fitted to).
PLATE_ROWS = [f"H{H}_Vf{v}_mu{m}" for H, vs in ((2, ("0.001", "0.01", "0.03", "0.05")), (1, ("0.01", "0.03", "0.05")))
              for m in ("0.22", "0.3", "0.6") for v in vs]
# (name, what it varies, the driver's arguments); the first is make figures' settings. Gray 2001 Sec 7.1 states
# L, H, the material, h = 1.5 dp, the kernel, the artificial stress and XSPH, and the initial mode (7.3)-(7.4);
# not the particles across H, the clamp, the viscosity, the time step or how the period is measured.
PLATE_VARIANTS = [
    ("as_make_figures", "none: n rows at half spacings, clamp 2, alpha = beta = 1, cfl 0.5, T = 2 t_1", []),
    ("centres_on_faces", "n + 1 rows, outer centres on the faces (PySPH's example): a plate H + dp thick",
     ["--centres-on-faces", "true"]),
    ("period_two_periods", "T as the mean of the first two full periods (to the third zero crossing)", ["--crossings", "3"]),
    ("period_one_period", "T between the first two zero crossings (one full period)", ["--crossings", "2"]),
    ("viscosity_half", "artificial viscosity alpha = beta = 0.5", ["--alpha", "0.5", "--beta", "0.5"]),
    ("viscosity_off", "no artificial viscosity (alpha = beta = 0)", ["--alpha", "0", "--beta", "0"]),
    ("clamp_1", "clamp length 1 (H at Table 2) instead of 2", ["--clamp-length", "1"]),
    ("step_half", "time-step factor 0.25 instead of 0.5", ["--cfl", "0.25"]),
]
STUDIES = {"plate": (PLATE_DRIVER, PLATE_ROWS, PLATE_VARIANTS, ("G-tab1", "G-tab2"), "T_sph_")}


def published(targets, prefix):
    """{quantity: (target, published, tolerance, compare, status kind)} of the studied rows."""
    out = {}
    for t in targets:
        for r in read_table(os.path.join(ROOT, "reference", f"{t}.csv")):
            if r["quantity"].startswith(prefix):
                kind = r["expect"] if r["expect"] != "discrepancy" else r.get("kind", "") or "discrepancy"
                out[r["quantity"]] = (t, float(r["published"]), float(r["tolerance"]), r["compare"], kind)
    return out


def job_dir(out, study, variant, row):
    return os.path.join(out, study, variant, row)


def done(d, driver):
    return os.path.exists(os.path.join(d, f"timing_{driver}.csv")) and os.path.exists(os.path.join(d, f"values_{driver}.csv"))


def run_job(binary, driver, args, row, d):
    os.makedirs(d, exist_ok=True)
    cmd = [os.path.join(binary, driver), "--rows", row, "--same-n-reading", "false", "--coarse-reference", "false",
           "--out", d] + args
    env = dict(os.environ, OMP_NUM_THREADS="1")
    with open(os.path.join(d, "log.txt"), "w") as log:
        rc = subprocess.call(cmd, stdout=log, stderr=subprocess.STDOUT, env=env)
    return row, d, rc, " ".join(cmd)


def values(d, driver):
    return {r["quantity"]: r["value"] for r in read_table(os.path.join(d, f"values_{driver}.csv"))}


def table(out, study, driver, rows, variants, targets, prefix):
    pub = published(targets, prefix)
    lines = []
    for name, what, _ in variants:
        dirs = [job_dir(out, study, name, row) for row in rows]
        if not all(done(d, driver) for d in dirs):
            print(f"studies: {study} {name}: {sum(done(d, driver) for d in dirs)} of {len(dirs)} jobs done: not in the table",
                  file=sys.stderr)
            continue
        for row, d in zip(rows, dirs):
            q = prefix + row
            if q not in pub:
                continue
            t, p, tol, compare, kind = pub[q]
            v = float(values(d, driver).get(q, "nan"))
            diff = v / p - 1 if compare == "rel" else v - p
            lines.append(dict(target=t, quantity=q, kind=kind, published=p, tolerance=tol, variant=name, choice=what,
                              value=f"{v:.6g}", difference=f"{diff:+.4f}", within=str(abs(diff) <= tol).lower()))
    path = os.path.join(out, f"{study}_sensitivity.csv")
    tmp = path + ".part"
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["target", "quantity", "kind", "published", "tolerance", "variant", "choice",
                                          "value", "difference", "within"])
        w.writeheader()
        w.writerows(lines)
    os.replace(tmp, path)
    print(f"studies: {study}: {len(lines)} values -> {path}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"))
    ap.add_argument("--out", default=os.path.join(ROOT, "results", "studies"))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--studies", default=",".join(STUDIES))
    ap.add_argument("--variants", default="", help="only these variants (comma-separated; default every one)")
    ap.add_argument("--list", action="store_true", help="print the jobs and exit")
    args = ap.parse_args()
    todo = []
    for study in args.studies.split(","):
        if study not in STUDIES:
            sys.exit(f"studies: no study {study!r} (there are: {', '.join(STUDIES)})")
        driver, rows, variants, _, _ = STUDIES[study]
        wanted = [w for w in args.variants.split(",") if w]
        unknown = [w for w in wanted if w not in [v[0] for v in variants]]
        if unknown:
            sys.exit(f"studies: {study} has no choice {', '.join(unknown)} (there are: {', '.join(v[0] for v in variants)})")
        chosen = [v for v in variants if not wanted or v[0] in wanted]
        for name, _, vargs in chosen:
            for row in rows:
                d = job_dir(args.out, study, name, row)
                if not done(d, driver):
                    todo.append((study, driver, vargs, row, d))
    if args.list:
        for study, driver, vargs, row, d in todo:
            print(study, row, " ".join(vargs), d)
        return 0
    failed = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = [pool.submit(run_job, args.bin, driver, vargs, row, d) for _, driver, vargs, row, d in todo]
        for i, f in enumerate(concurrent.futures.as_completed(futures), 1):
            row, d, rc, cmd = f.result()
            print(f"studies: [{i}/{len(todo)}] {d}: {'done' if rc == 0 else f'exit {rc} (log.txt)'}", flush=True)
            if rc != 0:
                failed.append(cmd)
    for study in args.studies.split(","):
        driver, rows, variants, targets, prefix = STUDIES[study]
        table(args.out, study, driver, rows, variants, targets, prefix)
    for cmd in failed:
        print(f"studies: FAILED: {cmd}", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
