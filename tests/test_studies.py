#!/usr/bin/env python3
"""tools/studies.py on made-up runs (issue 46 item 2): the sensitivity table takes each row's value from its own
job's values file, its difference from the reference row's published number under the row's compare and
tolerance, and leaves out a choice whose jobs have not all completed (no completion record: not read); and a
finished job is not run again (--list)."""
import csv
import importlib.util
import io
import os
import subprocess
import sys
import tempfile
from contextlib import redirect_stderr

HERE = os.path.dirname(os.path.abspath(__file__))
TOOL = os.path.join(HERE, "..", "tools", "studies.py")
spec = importlib.util.spec_from_file_location("studies", TOOL)
studies = importlib.util.module_from_spec(spec)
spec.loader.exec_module(studies)


def job(out, variant, row, value, complete=True):
    d = studies.job_dir(out, "plate", variant, row)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, f"values_{studies.PLATE_DRIVER}.csv"), "w") as f:
        f.write(f"# written by a test\nquantity,value,note\nT_sph_{row},{value},made up\n")
    if complete:
        with open(os.path.join(d, f"timing_{studies.PLATE_DRIVER}.csv"), "w") as f:
            f.write("target,driver,wall_s,particle_steps,threads\nG-tab1,x,1,1,1\n")


def main():
    failures = []
    pub = studies.published(("G-tab1", "G-tab2"), "T_sph_")
    rows = ["H2_Vf0.05_mu0.6", "H1_Vf0.01_mu0.3"]
    variants = [("a", "choice a", []), ("b", "choice b", []), ("c", "choice c", [])]
    with tempfile.TemporaryDirectory() as out:
        # a: one row 1% above its published period (within 3%), the other 5% above (not); b: exact; c: one job
        # without its completion record (a killed run): the whole choice is left out.
        for row, f in zip(rows, (1.01, 1.05)):
            job(out, "a", row, pub["T_sph_" + row][1] * f)
            job(out, "b", row, pub["T_sph_" + row][1])
        job(out, "c", rows[0], 1.0)
        job(out, "c", rows[1], 1.0, complete=False)
        err = io.StringIO()
        with redirect_stderr(err):
            studies.table(out, "plate", studies.PLATE_DRIVER, rows, variants, ("G-tab1", "G-tab2"), "T_sph_")
        with open(os.path.join(out, "plate_sensitivity.csv")) as f:
            got = {(r["variant"], r["quantity"]): r for r in csv.DictReader(f)}
        expect = {("a", "T_sph_H2_Vf0.05_mu0.6"): ("+0.0100", "true"), ("a", "T_sph_H1_Vf0.01_mu0.3"): ("+0.0500", "false"),
                  ("b", "T_sph_H2_Vf0.05_mu0.6"): ("+0.0000", "true"), ("b", "T_sph_H1_Vf0.01_mu0.3"): ("+0.0000", "true")}
        if set(got) != set(expect):
            failures.append(f"table rows {sorted(got)}, expected {sorted(expect)} (choice c incomplete: left out)")
        for key, (diff, within) in expect.items():
            if key in got and (got[key]["difference"], got[key]["within"]) != (diff, within):
                failures.append(f"{key}: {got[key]['difference']} {got[key]['within']}, expected {diff} {within}")
        if "c: 1 of 2 jobs done" not in err.getvalue():
            failures.append(f"an incomplete choice is not reported: {err.getvalue()!r}")
        # --list: the jobs left to run; a finished one is not among them. An unknown choice is refused.
        first = studies.PLATE_ROWS[0]
        job(out, "clamp_1", first, 1.0)
        listed = subprocess.run([sys.executable, TOOL, "--out", out, "--list", "--variants", "clamp_1"],
                                capture_output=True, text=True, check=True).stdout.splitlines()
        if len(listed) != len(studies.PLATE_ROWS) - 1 or any(l.split()[1] == first for l in listed):
            failures.append(f"--list of clamp_1 with its first job done: {listed!r}")
        bad = subprocess.run([sys.executable, TOOL, "--out", out, "--list", "--variants", "no_such"], capture_output=True, text=True)
        if bad.returncode == 0 or "no choice no_such" not in bad.stderr:
            failures.append(f"an unknown choice was not refused: {bad.returncode} {bad.stderr!r}")
    for f in failures:
        print("FAIL:", f)
    print(f"test_studies: {'FAILED' if failures else 'every case holds'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
