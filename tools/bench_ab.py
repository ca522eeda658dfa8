#!/usr/bin/env python3
"""make bench-ab BASE=<rev>: the scene benchmarks of this checkout against those of another revision, alternated.

  tools/bench_ab.py --base REV [--rounds 3] [--benches bench_gray_scenes,bench_hexagon] [--out results/bench_ab.csv]

A speed-up is a ratio measured in one sitting: this shared machine's speed drifts by up to 1.5x between
sittings, so throughputs from different days do not compare. This script builds the benchmark drivers of
REV (a clone under $WORK, default /tmp/bench_ab/<rev>, Release, as CMakeLists.txt sets it) and runs them
and ours (build/bin, which make builds first) in turn, base then ours, --rounds times, each with
--out into a scratch folder. Every row of a benchmark's CSV (scene, variant, particles, threads) with a
throughput (particle_steps_per_s > 0) is collected on both sides; the table gives the median of each side
and the ratio ours / base of the medians, with min and max of the pairwise ratios (a wide range says the
machine was noisy). Writes --out (columns scene,variant,particles,threads,base,ours,base_median,
ours_median,ratio,ratio_min,ratio_max; the '#' header records both revisions and the commands) and prints it.
Extra arguments of a benchmark: --args 'bench_tl_hole=--n 81' (repeatable): the base must accept them too.
Both sides built with other CMake arguments (e.g. --cmake-args '-DSPH_NATIVE=OFF "-DCMAKE_CXX_FLAGS=-march=native
-mno-avx512f"', an AVX2 build on an AVX-512 host): the base in its clone's build-ab/, ours in this checkout's
build-ab/ (instead of --ours).
"""
import argparse
import csv
import os
import shlex
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(cmd, **kw):
    return subprocess.run(cmd, check=True, **kw)


def git(*args):
    return subprocess.run(["git", "-C", HERE, *args], check=True, capture_output=True, text=True).stdout.strip()


def build(src, folder, cmake_args, benches, jobs):
    """The bench binaries of the checkout `src`, built in src/folder; returns their folder."""
    build = os.path.join(src, folder)
    run(["cmake", "-S", src, "-B", build, "-DCMAKE_BUILD_TYPE=Release", *cmake_args], stdout=subprocess.DEVNULL)
    run(["cmake", "--build", build, "-j", str(jobs), "--target", *benches], stdout=subprocess.DEVNULL)
    return os.path.join(build, "bin")


def build_base(rev, benches, work, jobs, cmake_args):
    """The bench binaries of revision `rev`, built in a clone of this repository under `work`."""
    sha = git("rev-parse", "--short=12", rev)
    src = os.path.join(work, sha)
    if not os.path.isdir(src):
        os.makedirs(work, exist_ok=True)
        run(["git", "clone", "-q", HERE, src])
        run(["git", "-C", src, "checkout", "-q", sha])
    return sha, build(src, "build-ab" if cmake_args else "build", cmake_args, benches, jobs)


def throughputs(path):
    """{(scene, variant, particles, threads): particle-steps per second} of a benchmark CSV."""
    with open(path) as f:
        rows = list(csv.DictReader(l for l in f if not l.startswith("#")))
    out = {}
    for r in rows:
        rate = float(r["particle_steps_per_s"])
        if rate > 0:
            out[(r["scene"], r["variant"], r["particles"], r["threads"])] = rate
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--base", required=True, help="git revision to compare against (e.g. a commit before a speed-up)")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--benches", default="bench_gray_scenes,bench_hexagon")
    ap.add_argument("--args", action="append", default=[], help="BENCH=ARGS, extra arguments of one benchmark")
    ap.add_argument("--ours", default=os.path.join(HERE, "build", "bin"))
    ap.add_argument("--out", default=os.path.join(HERE, "results", "bench_ab.csv"))
    ap.add_argument("--work", default=os.environ.get("WORK", "/tmp/bench_ab"))
    ap.add_argument("--cmake-args", default="", help="CMake arguments of both sides (ours then in build-ab/)")
    a = ap.parse_args()
    cmake_args = shlex.split(a.cmake_args)
    if a.rounds < 1:
        sys.exit("bench_ab: --rounds must be at least 1")
    benches = [b for b in a.benches.split(",") if b]
    extra = {}
    for spec in a.args:
        name, sep, args = spec.partition("=")
        if not sep or name not in benches:
            sys.exit(f"bench_ab: --args {spec!r}: expected BENCH=ARGS with BENCH one of {benches}")
        extra[name] = shlex.split(args)
    if cmake_args:
        a.ours = build(HERE, "build-ab", cmake_args, benches, os.cpu_count() or 2)
    for b in benches:
        if not os.access(os.path.join(a.ours, b), os.X_OK):
            sys.exit(f"bench_ab: {os.path.join(a.ours, b)} is missing: build it first (make build)")
    base_sha, base_bin = build_base(a.base, benches, a.work, os.cpu_count() or 2, cmake_args)
    ours_rev = git("describe", "--always", "--dirty", "--abbrev=12")
    rates = {"base": {}, "ours": {}}
    commands = []
    with tempfile.TemporaryDirectory(prefix="bench_ab_") as tmp:
        for r in range(a.rounds):
            for b in benches:
                for side, bindir in (("base", base_bin), ("ours", a.ours)):
                    out = os.path.join(tmp, side)
                    cmd = [os.path.join(bindir, b), "--out", out, *extra.get(b, [])]
                    if r == 0:
                        commands.append(" ".join(cmd))
                    print(f"bench_ab: round {r + 1}/{a.rounds}: {side} {b}", flush=True)
                    run(cmd, stdout=subprocess.DEVNULL)
                    for key, rate in throughputs(os.path.join(out, b + ".csv")).items():
                        rates[side].setdefault(key, []).append(rate)
    keys = [k for k in rates["ours"] if k in rates["base"]]
    cols = ["scene", "variant", "particles", "threads", "base", "ours", "base_median", "ours_median", "ratio",
            "ratio_min", "ratio_max"]
    os.makedirs(os.path.dirname(os.path.abspath(a.out)), exist_ok=True)
    with open(a.out, "w", newline="") as f:
        f.write(f"# base = {a.base} ({base_sha})\n# ours = {ours_rev} ({a.ours})\n# rounds = {a.rounds}, "
                "alternated base then ours\n")
        if cmake_args:
            f.write(f"# cmake args of both = {a.cmake_args}\n")
        for c in commands:
            f.write(f"# command = {c}\n")
        w = csv.writer(f)
        w.writerow(cols)
        print(f"{'scene':22} {'variant':36} {'particles':>9} {'thr':>3} {'base':>10} {'ours':>10} {'ratio':>6} (min-max)")
        for k in keys:
            b, o = rates["base"][k], rates["ours"][k]
            pair = [y / x for x, y in zip(b, o)]
            mb, mo = statistics.median(b), statistics.median(o)
            w.writerow([*k, base_sha, ours_rev, f"{mb:.6g}", f"{mo:.6g}", f"{mo / mb:.4f}", f"{min(pair):.4f}",
                        f"{max(pair):.4f}"])
            print(f"{k[0]:22} {k[1][:36]:36} {k[2]:>9} {k[3]:>3} {mb:10.3g} {mo:10.3g} {mo / mb:6.3f} "
                  f"({min(pair):.3f}-{max(pair):.3f})")
    print(f"bench_ab: {len(keys)} rows, ours {ours_rev} against {a.base} ({base_sha}) -> {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
