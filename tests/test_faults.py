#!/usr/bin/env python3
"""Faults a pipeline meets (issue 47), each tried and its outcome tabled, as tests/test_bad_input.py does for bad
input: two pipelines into one results folder (item 2; tools/results_lock.sh, taken by make figures and make
test), a run killed at any instant (item 3: outputs written as <name>.part and renamed when complete,
src/io/atomic_output.hpp) and a write that fails (item 4). The run-length refusal (item 1) is a class of
tests/test_bad_input.py.

  second make figures   a `make figures` into a folder whose lock another pipeline holds: refused at once (no
                        build, no run), naming the holder; the holder's folder untouched
  after the holder      the same folder once the holder has ended: the lock is taken
  killed holder         a holder killed with SIGKILL (no trap runs): the kernel has released the lock; its info
                        file left behind is taken over with a line saying so
  SIGKILL at t          a quick driver (CSV traces, values, HDF5 snapshots) killed at instants from before its
                        first write to after its last (seeded): every file of its folder is the previous complete
                        run's or none (no half file under a final name); the completion record is present only if
                        the run completed; the .part files left are read by nothing
  file-size limit       the same driver under `ulimit -f` (EFBIG, as a full disk gives ENOSPC: the same failed
                        write): exit 1 with one line naming the file and errno, no completion record, no final file
  full disk             the same on a 64 kB tmpfs, where mounting one is allowed (else the row says it was not tried)

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


KILL_DRIVER = "gray2001_fig6_7_rings"  # quick: ~1.5 s, writes traces, frames, values, summary and two HDF5 series
KILL_TARGET = "G-fig6"
CHECK = os.path.join(ROOT, "reference", "check.py")


def check_says(results):
    """The check of the killed driver's target on `results` (quick rows): (exit code, its output)."""
    p = subprocess.run([sys.executable, CHECK, "--results", results, "--quick", "--targets", KILL_TARGET,
                        "--any-version"], capture_output=True, text=True, timeout=300)
    return p.returncode, p.stdout + p.stderr


def values_text(folder):
    with open(os.path.join(folder, f"values_{KILL_DRIVER}.csv")) as f:
        return "".join(l for l in f if not l.startswith("# date = "))


def folder_state(folder):
    """What makes each file of a run folder whole: a CSV's shape (lines, cells per line, a final line break; its
    wall times and date differ between two runs of one binary and one set of parameters), an HDF5 series' size (its
    only run-dependent content, the date attribute, has a fixed length), any other file's text."""
    state = {}
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if name.endswith((".h5", ".h5.part")):
            state[name] = os.path.getsize(path)
            continue
        with open(path, errors="replace") as f:
            text = f.read()
        if name.endswith((".csv", ".csv.part")):
            state[name] = (text.endswith("\n"), tuple(len(l.split(",")) for l in text.splitlines() if not l.startswith("#")))
        else:
            state[name] = text
    return state


def kill_at_instants(bin_dir, tmp, seeds):
    """Runs the driver once to completion (the previous run), then, per seed, again into the same folder, killed
    with SIGKILL at a random instant of [0, 1.3 x its run time]. After each kill: every file whole or absent, the
    check refusing the target by name unless the run had completed; at the end, a rerun gives the values of the
    uninterrupted run. Returns (instants tried, problems found)."""
    import random
    exe = os.path.join(bin_dir, KILL_DRIVER)
    results = os.path.join(tmp, "killed_results")
    folder = os.path.join(results, KILL_TARGET)
    env = dict(os.environ, OMP_NUM_THREADS="1")
    start = time.monotonic()
    subprocess.run([exe, "--quick", "--out", folder], env=env, check=True, capture_output=True)
    took = time.monotonic() - start
    complete = {k: v for k, v in folder_state(folder).items()}
    uninterrupted = values_text(folder)
    record = f"timing_{KILL_DRIVER}.csv"
    problems, instants = [], []
    for seed in seeds:
        at = random.Random(seed).uniform(0.0, 1.3 * took)
        instants.append(at)
        p = subprocess.Popen([exe, "--quick", "--out", folder], env=env, stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL)
        time.sleep(at)
        p.send_signal(signal.SIGKILL)
        p.wait()
        now = folder_state(folder)
        for name, content in now.items():
            if name.endswith(".part"):
                continue
            if name not in complete:
                problems.append(f"seed {seed} at {at:.2f} s: {name} is not a file of a complete run")
            elif content != complete[name]:
                problems.append(f"seed {seed} at {at:.2f} s: {name} is not whole (not the shape of a complete run's)")
        if record in now and set(n for n in now if not n.endswith(".part")) != set(complete):
            problems.append(f"seed {seed} at {at:.2f} s: a completion record without every file of the run")
        code, said = check_says(results)
        if record not in now and (code == 0 or "did not complete" not in said):
            problems.append(f"seed {seed} at {at:.2f} s: the check did not refuse the incomplete run (exit {code})")
        if record in now and "did not complete" in said:
            problems.append(f"seed {seed} at {at:.2f} s: the check refused a complete run")
    subprocess.run([exe, "--quick", "--out", folder], env=env, check=True, capture_output=True)
    if values_text(folder) != uninterrupted:
        problems.append("the rerun after the kills gave other values than the uninterrupted run")
    return instants, problems


def failed_write(bin_dir, tmp, folder, limit_kb=None):
    """The driver writing into `folder` under a file-size limit (limit_kb) or as it is: (exit code, its last
    line, the final-named files it left)."""
    exe = os.path.join(bin_dir, KILL_DRIVER)
    cmd = f"ulimit -f {limit_kb}; exec {exe} --quick --out {folder}" if limit_kb else f"exec {exe} --quick --out {folder}"
    p = subprocess.run(["bash", "-c", cmd], capture_output=True, text=True, timeout=120,
                       env=dict(os.environ, OMP_NUM_THREADS="1"))
    lines = p.stderr.strip().splitlines()
    left = [n for n in os.listdir(folder) if not n.endswith(".part")] if os.path.isdir(folder) else []
    return p.returncode, (lines[-1] if lines else ""), len(lines), left


def full_disk(bin_dir, tiny):
    """The driver writing onto a 64 kB tmpfs, mounted in a mount namespace of its own (unshare: the system's mounts
    are not touched, and the tmpfs goes with the namespace). Returns failed_write's tuple, with the final-named
    files listed inside the namespace; (None, why, 0, []) where such a namespace is not allowed."""
    exe = os.path.join(bin_dir, KILL_DRIVER)
    os.makedirs(tiny)
    script = (f"mount -t tmpfs -o size=64k tmpfs {tiny} || exit 99; {exe} --quick --out {tiny}/out; rc=$?; "
              f"echo; echo LEFT; ls -A {tiny}/out 2>/dev/null | grep -v '[.]part$'; exit $rc")
    for prefix in (["unshare", "--mount", "--propagation", "private"], ["unshare", "--map-root-user", "--mount"]):
        p = subprocess.run(prefix + ["sh", "-c", script], capture_output=True, text=True, timeout=120,
                           env=dict(os.environ, OMP_NUM_THREADS="1"))
        if p.returncode != 99 and "unshare:" not in p.stderr:
            left = p.stdout.split("LEFT\n", 1)[1].split() if "LEFT\n" in p.stdout else []
            lines = p.stderr.strip().splitlines()
            return p.returncode, (lines[-1] if lines else ""), len(lines), left
    return None, (p.stderr.strip().splitlines() or ["?"])[-1], 0, []


def run(cmd, timeout=30):
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    return p.returncode, (p.stderr.strip() or p.stdout.strip())


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--table", default=None)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"), help="the drivers' folder")
    ap.add_argument("--seeds", type=int, default=8, help="SIGKILL instants tried")
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

        instants, problems = kill_at_instants(args.bin, tmp, range(1, args.seeds + 1))
        record(f"SIGKILL at t ({len(instants)} instants)", "the previous run's files or none; .part files",
               -9, f"instants {min(instants):.2f}..{max(instants):.2f} s; " + ("; ".join(problems[:3]) or
               "every file whole or absent, no record without the run"), not problems)

        def write_fault(name, folder, limit_kb, errno_text):
            code, last, nlines, left = failed_write(args.bin, tmp, folder, limit_kb)
            record(name, ", ".join(left) or "no file", code, last,
                   code == 1 and nlines == 1 and ".part" in last and errno_text in last and not left)

        write_fault("file-size limit", os.path.join(tmp, "limited"), 8, "(errno 27)")
        code, last, nlines, left = full_disk(args.bin, os.path.join(tmp, "tiny"))
        if code is None:
            record("full disk", "not tried", 0, "a mount namespace with a small tmpfs is not allowed here: " + last, True)
        else:
            record("full disk", ", ".join(left) or "no file", code, last,
                   code == 1 and nlines == 1 and ".part" in last and "(errno 28)" in last and not left)

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
