#!/usr/bin/env python3
"""An interrupted `make figures` leaves nothing that looks complete, and the next make resumes where it stopped.

Through the Makefile's own target rules (results/<target>/.done, the quick runs of `make test`): G-disp, a
driver of milliseconds, then G-tab1, whose values file is written from its first second on. The make is
interrupted while G-tab1 runs, by SIGINT (Ctrl-C: to the whole process group, as a terminal sends it) and,
in a second run, by SIGTERM. Then:
  - make exits non-zero; G-disp is complete (.done, its completion record); G-tab1 has no .done, no
    completion record (timing_<driver>.csv) and no values file: only its temporary <name>.part, which nothing
    reads (outputs are renamed when complete, src/io/atomic_output.hpp);
  - reference/check.py refuses G-tab1's rows, naming the values file that is not there;
  - the same make again runs only G-tab1 (G-disp's completion record is not rewritten) and completes it, and
    the check then accepts its rows.
Usage: test_interrupt.py --build BUILD_DIR (ctest passes it; the drivers must have been built there).
"""
import argparse
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import pandas as pd

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = None
FIRST, SECOND = "G-disp", "G-tab1"
SECOND_DRIVER = "gray2001_table1_2_plate_periods"


def make(results, **popen):
    # G-tab1_RUN_DRIVER empty: its rows are not run jobs here, so that its own driver run steps them and is interrupted
    # while it does (as jobs, the row would be stepped before the driver starts, which then only collects it).
    cmd = ["make", "-s", "-C", ROOT, f"BUILD={BUILD}", f"RESULTS={results}", "DRIVER_FLAGS=--quick", f"{SECOND}_RUN_DRIVER=",
           f"{results}/{FIRST}/.done", f"{results}/{SECOND}/.done"]
    # A make of its own, not a sub-make of the `make test` that runs ctest (whose jobserver it cannot reach).
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL", "MAKEOVERRIDES")}
    env["OMP_NUM_THREADS"] = "1"
    return subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, **popen)


def check(results):
    cmd = [sys.executable, os.path.join(ROOT, "reference", "check.py"), "--results", results, "--targets", SECOND,
           "--quick"]
    out = subprocess.run(cmd, capture_output=True, text=True)
    table = pd.read_csv(os.path.join(results, "check.csv"), dtype=str, keep_default_na=False)
    return out.returncode, table


class Interrupted(unittest.TestCase):
    def interrupt_and_resume(self, sig):
        with tempfile.TemporaryDirectory() as results:
            values = os.path.join(results, SECOND, f"values_{SECOND_DRIVER}.csv")
            p = make(results, start_new_session=True)
            deadline = time.time() + 120
            while not os.path.exists(values + ".part") and p.poll() is None and time.time() < deadline:
                time.sleep(0.05)
            self.assertIsNone(p.poll(), "make ended before the second target's driver had started")
            time.sleep(0.5)  # inside the run: its values file is open, its rows being computed
            os.killpg(p.pid, sig)
            out, _ = p.communicate(timeout=60)
            self.assertNotEqual(p.returncode, 0, out)

            self.assertTrue(os.path.exists(os.path.join(results, FIRST, ".done")))
            first_record = [f for f in os.listdir(os.path.join(results, FIRST)) if f.startswith("timing_")]
            self.assertEqual(len(first_record), 1)
            first_mtime = os.path.getmtime(os.path.join(results, FIRST, first_record[0]))
            self.assertFalse(os.path.exists(os.path.join(results, SECOND, ".done")))
            self.assertFalse(os.path.exists(values))  # not complete: only its .part, which nothing reads
            self.assertFalse(os.path.exists(os.path.join(results, SECOND, f"timing_{SECOND_DRIVER}.csv")))
            code, table = check(results)  # the check refuses the target's rows, by the file's name
            self.assertEqual(code, 1)
            self.assertGreater(len(table), 0)
            for _, r in table.iterrows():
                self.assertEqual(r["status"], "FAIL", r["quantity"])
                self.assertTrue("did not complete" in r["note"] or "no reproduced value" in r["note"], r["note"])
            self.assertTrue(any("did not complete" in n and f"values_{SECOND_DRIVER}.csv" in n for n in table["note"]),
                            table["note"].tolist())

            p = make(results)
            out, _ = p.communicate(timeout=600)
            self.assertEqual(p.returncode, 0, out)
            self.assertEqual(os.path.getmtime(os.path.join(results, FIRST, first_record[0])), first_mtime)
            self.assertTrue(os.path.exists(os.path.join(results, SECOND, ".done")))
            code, table = check(results)
            self.assertEqual(code, 0, table.to_string())

    def test_sigint(self):
        self.interrupt_and_resume(signal.SIGINT)

    def test_sigterm(self):
        self.interrupt_and_resume(signal.SIGTERM)


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    args, rest = ap.parse_known_args()
    BUILD = os.path.abspath(args.build)
    result = unittest.main(argv=[sys.argv[0]] + rest, exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
