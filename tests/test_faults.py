#!/usr/bin/env python3
"""Faults a pipeline meets (issue 47), each tried and its outcome tabled, as tests/test_bad_input.py does for bad
input. So far: two pipelines into one results folder (item 2; tools/results_lock.sh, taken by make figures and
make test). The run-length refusal (item 1) is a class of tests/test_bad_input.py.

  second make figures   a `make figures` into a folder whose lock another pipeline holds: refused at once (no
                        build, no run), naming the holder; the holder's folder untouched
  after the holder      the same folder once the holder has ended: the lock is taken
  killed holder         a holder killed with SIGKILL (no trap runs): the kernel has released the lock; its info
                        file left behind is taken over with a line saying so

Writes the table (fault, what was left, outcome) to --table. Usage: test_faults.py [--table FILE]
"""
import argparse
import csv
import os
import signal
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LOCK = os.path.join(ROOT, "tools", "results_lock.sh")


def hold(folder, what, seconds=60):
    """A pipeline holding the folder's lock: results_lock.sh running `sleep`; returns once the lock is held."""
    p = subprocess.Popen([LOCK, folder, what, "sleep", str(seconds)], start_new_session=True,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    info = os.path.join(folder, ".lock.info")
    for _ in range(200):
        if os.path.exists(info) and what in open(info).read():
            return p
        time.sleep(0.02)
    raise RuntimeError("the holder did not take the lock")


def run(cmd, timeout=30):
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    return p.returncode, (p.stderr.strip() or p.stdout.strip())


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--table", default=None)
    args = ap.parse_args()
    rows, failures = [], []

    def record(fault, left, code, message, ok):
        rows.append({"fault": fault, "left": left, "exit_code": code, "outcome": message})
        if not ok:
            failures.append(f"{fault}: exit {code}, {message!r}")

    with tempfile.TemporaryDirectory() as tmp:
        folder = os.path.join(tmp, "results")
        holder = hold(folder, "make figures (the first)")
        marker = os.path.join(folder, "the_first_pipelines_file")
        open(marker, "w").close()
        start = time.monotonic()
        code, message = run(["make", "-s", "-C", ROOT, f"RESULTS={folder}", f"BUILD={os.path.join(tmp, 'no_build')}",
                             "figures"])
        took = time.monotonic() - start
        record("second make figures", "the first pipeline's files", code, message,
               code != 0 and "refused" in message and f"pid {holder.pid}" in message and "the first" in message
               and took < 10 and os.path.exists(marker) and not os.path.exists(os.path.join(tmp, "no_build")))

        os.killpg(holder.pid, signal.SIGTERM)  # the pipeline ends (its children too: they hold the lock as well)
        holder.wait()
        code, message = run([LOCK, folder, "the next", "echo", "ran"])
        record("after the holder", "nothing", code, message, code == 0 and message == "ran")

        holder = hold(folder, "a killed pipeline")
        os.killpg(holder.pid, signal.SIGKILL)
        holder.wait()
        code, message = run([LOCK, folder, "the next", "true"])
        record("killed holder", "its .lock.info", code, message,
               code == 0 and "taking over" in message and "a killed pipeline" in message)

    if args.table:
        with open(args.table, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]))
            w.writeheader()
            w.writerows(rows)
    for r in rows:
        print(f"{r['fault']:22s} exit {r['exit_code']}: {r['outcome']}")
    print(f"{len(rows)} faults tried, {len(failures)} not handled")
    for f in failures:
        print("  " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
