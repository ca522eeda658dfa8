#!/usr/bin/env python3
"""Every driver refuses bad input clearly: a non-zero exit and one line that names the parameter and the value.

For every driver of experiments/targets.mk (and the benchmarks), each class of bad input the driver has, found
from its own --help:
  unknown option       --no-such-option 1
  unparsable number    its first number option set to 'abc'
  out of range         its first option bounded below (':> x' or ':>= x' in --help) set to x - 1
  unknown name         its first option with a list of allowed names (':{...}') set to 'nosuchname'
  unwritable output    --out below a regular file (root may write anywhere else)
  run too long         a time step of 1e-30 (--cfl) in a driver that steps a run to a fixed end: refused by the
                       run-length guard (frame/progress.hpp) after its first 2 s, naming the estimate and the flag
  too many particles   its particle spacing (--dp, --ps, --slab-dp, --rings-dp, --plate-dp) set to 2^-30
                       (~1e-9, dividing every length), or its particles along a side (--n) to 1e8-1e9:
                       refused before anything is allocated
Each run has 60 s and an address-space limit of 4 GiB (not in a sanitizer build, whose shadow memory needs
more), so that a driver that did allocate fails here instead of taking the machine's memory. Writes the table (driver, input, exit code, message) to --table.
Usage: test_bad_input.py --build BUILD_DIR [--table FILE]
"""
import argparse
import csv
import os
import re
import resource
import subprocess
import sys
import tempfile

sys.dont_write_bytecode = True
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "experiments"))
import targets as declaration  # noqa: E402

SANITIZED = False
SPACINGS = ("dp", "ps", "slab-dp", "rings-dp", "plate-dp")
OPTION = re.compile(r"^\s+--([a-z0-9-]+) (FLOAT|INT|UINT|TEXT)(\S*)")
TINY = f"{2.0 ** -30!r}"  # a spacing that divides every length of the scenes (a power of two), ~1e-9


def sanitized(build):
    """A build with the sanitizers (make sanitize): AddressSanitizer reserves terabytes of address space for its
    shadow memory, so it cannot run under an address-space limit (it reports a huge allocation itself)."""
    try:
        with open(os.path.join(build, "CMakeCache.txt")) as f:
            return "SPH_SANITIZE:BOOL=ON" in f.read()
    except OSError:
        return False


def limit_memory():
    if not SANITIZED:
        resource.setrlimit(resource.RLIMIT_AS, (4 << 30, 4 << 30))


def run(binary, args, out_dir):
    if "--out" not in args:
        args = args + ["--out", out_dir]
    try:
        p = subprocess.run([binary] + args, capture_output=True, text=True, timeout=60, preexec_fn=limit_memory,
                           env=dict(os.environ, OMP_NUM_THREADS="1"))
        text = (p.stderr.strip() or p.stdout.strip()).splitlines()
        return p.returncode, text
    except subprocess.TimeoutExpired:
        return "timeout", ["(no answer in 60 s)"]


def options(binary):
    """[(name, type, usage with its constraints, is a list)] and the text of the driver's --help."""
    out = subprocess.run([binary, "--help"], capture_output=True, text=True, timeout=30).stdout
    # (a list option's usage ends in '...', before the two spaces that start its help text)
    return [(m.group(1), m.group(2), l.strip().split("  ")[0], l.strip().split("  ")[0].endswith("..."))
            for l in out.splitlines() for m in [OPTION.match(l)] if m], out


# Drivers whose first run steps to a fixed end time with the time-step factor --cfl (each scene kind once: plate,
# rings, slab, the total-Lagrangian plate of the cures table): the run-length guard must refuse --cfl 1e-30.
STEPS_TO_AN_END = ("gray2001_table1_2_plate_periods", "gray2001_fig6_7_rings", "gray2001_fig8_10_slab",
                   "gray2001_tensile_cures")


def name_of(binary):
    return os.path.basename(binary)


def cases(binary, tmp):
    """(class, args, what the message must name) for every class of bad input the driver has."""
    opts, helptext = options(binary)
    out = [("unknown option", ["--no-such-option", "1"], ["--no-such-option"])]
    number = next((o for o in opts if o[1] in ("FLOAT", "INT", "UINT")), None)
    if number:
        out.append(("unparsable number", [f"--{number[0]}", "abc"], [f"--{number[0]}", "abc"]))
    bounded = next((o for o in opts if re.search(r":>=? ", o[2])), None)
    if bounded:
        lo = float(re.search(r":>=? (-?[0-9.e+-]+)", bounded[2]).group(1))
        value = f"{lo - 1:g}"
        out.append(("out of range", [f"--{bounded[0]}", value], [f"--{bounded[0]}", value, "out of range"]))
    named = next((o for o in opts if ":{" in o[2]), None)
    if named:
        out.append(("unknown name", [f"--{named[0]}", "nosuchname"], [f"--{named[0]}", "nosuchname"]))
    blocker = os.path.join(tmp, "a_file")
    open(blocker, "w").close()
    out.append(("unwritable output", ["--out", os.path.join(blocker, "out")], ["--out", "cannot write"]))
    names = {o[0]: o for o in opts}
    if name_of(binary) in STEPS_TO_AN_END:
        out.append(("run too long", ["--quick", "--cfl", "1e-30"], ["would take", "years", "--max-run-hours 0"]))
    spacing = next((s for s in SPACINGS if s in names), None)
    n_is_count = any(l.strip().startswith("--n INT") and "particles" in l for l in helptext.splitlines())
    if spacing:
        out.append(("too many particles", [f"--{spacing}", TINY], ["particles", "coarser spacing"]))
    elif n_is_count:
        n = ["100000000", "200000000", "300000000", "400000000"] if names["n"][3] else ["1000000000"]
        out.append(("too many particles", ["--n"] + n, ["particles", "coarser spacing"]))
    return out


def drivers():
    names = []
    d = declaration.read()
    for t in d.targets:
        names += [x for x in t.drivers if x not in names]
    return names + [b for b in d.bench_drivers if b not in names]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--table", default=None)
    args = ap.parse_args()
    global SANITIZED
    SANITIZED = sanitized(args.build)
    rows, failures = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for name in drivers():
            binary = os.path.join(args.build, "bin", name)
            for klass, argv, must in cases(binary, tmp):
                code, lines = run(binary, argv, os.path.join(tmp, "out"))
                message = " | ".join(lines[:2])
                rows.append({"driver": name, "input": klass, "arguments": " ".join(argv), "exit_code": code,
                             "message": message})
                named = all(m in " ".join(lines) for m in must)
                if code == 0 or code == "timeout" or not named or len(lines) > 2:  # one line (+ CLI11's --help hint): refused before any run
                    failures.append(f"{name} {' '.join(argv)}: exit {code}, {message!r} (must name {must})")
    if args.table:
        with open(args.table, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]))
            w.writeheader()
            w.writerows(rows)
    classes = sorted({r["input"] for r in rows})
    for k in classes:
        n = sum(r["input"] == k for r in rows)
        print(f"{k:20s} {n:3d} drivers")
    print(f"{len(rows)} bad inputs tried, {len(failures)} not refused clearly")
    for f in failures:
        print("  " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
