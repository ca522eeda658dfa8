#!/usr/bin/env python3
"""tools/timings.py on made-up timing records: the merged table, and the critical path (issue 17: the drivers' time
with a node for every job), where a split target's runs go side by side before its own driver invocations, which go
one after another."""
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TOOL = os.path.join(HERE, "..", "tools", "timings.py")
COLS = "target,driver,wall_s,particle_steps,threads\n"
OLD_COLS = "target,driver,wall_s,particle_steps,threads,reused_particle_steps\n"  # records before issue 45


def record(path, target, driver, wall, old=False):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write("# written by a test\n" + (OLD_COLS if old else COLS) + f"{target},{driver},{wall},1000,1" +
                (",500\n" if old else "\n"))


def main():
    failures = []
    with tempfile.TemporaryDirectory() as results:
        # A: two drivers, one after another: 10 + 5. B: runs of 20 and 30 side by side, then its collector 1: 31.
        # C: one driver of 25. The critical path is B's 31 s (not C's 25, not the sum of B's runs, 51).
        record(os.path.join(results, "A", "timing_a1.csv"), "A", "a1", 10)
        record(os.path.join(results, "A", "timing_a2.csv"), "A", "a2", 5)
        record(os.path.join(results, ".runs", "B", "r1", "timing_b.csv"), "B", "b", 20)
        record(os.path.join(results, ".runs", "B", "r2", "timing_b.csv"), "B", "b", 30)
        record(os.path.join(results, "B", "timing_b.csv"), "B", "b", 1)
        record(os.path.join(results, "C", "timing_c.csv"), "C", "c", 25, old=True)
        out = subprocess.run([sys.executable, TOOL, "--results", results], capture_output=True, text=True)
        if out.returncode != 0:
            failures.append(f"timings.py exited {out.returncode}: {out.stderr}")
        if "critical path 31 s (B)" not in out.stdout:
            failures.append(f"expected 'critical path 31 s (B)' in:\n{out.stdout}")
        if "6 driver runs, 91 s in the drivers, 6000 particle-steps" not in out.stdout:
            failures.append(f"expected the totals '6 driver runs, 91 s in the drivers, 6000 particle-steps' in:\n{out.stdout}")
        with open(os.path.join(results, "timings.csv")) as f:
            lines = f.read().splitlines()
        if len(lines) != 7 or not lines[1].startswith("B/r2,b,30.000"):
            failures.append("timings.csv: expected 6 rows, the longest (B/r2, 30 s) first:\n" + "\n".join(lines))
    for msg in failures:
        print("FAIL:", msg)
    print(f"test_timings: {'FAIL' if failures else 'ok'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
