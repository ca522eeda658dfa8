#!/usr/bin/env python3
"""Gray, Monaghan & Swift 2001's colliding rubber rings (Sec 7.2) in LAMMPS's MACHDYN (pair smd/ulsph, a plugin of
Debian's lmp: tools/peers/build_machdyn.sh), from our particles, with its frames in our format.

  1. reads our layout (build/bin/peer_rings --action layout: layout.csv, settings.csv) and writes it as a LAMMPS data
     file (atom_style smd: type = ring + 1, volume dp^2, our mass, radius = h so that the kernel support r_i + r_j is
     our 2h, contact radius dp/2, our velocities);
  2. lists the steps at which our run samples (sph::Cadence: the first step whose accumulated t = sum dt has reached
     the next multiple of sample_dt, to 1e-12) with our dt, fixed;
  3. runs tools/peers/lammps_rings.in (our dt, t_max / dt steps, eps of the artificial stress 0 or --art-stress)
     with lmp from the repository root;
  4. converts its dump (id x y vx vy at those steps) into our frames file (experiments/peers/frames_reader.hpp:
     t,id,x,y,u,v, id = our layout's row), t being our accumulated time at that step, and writes FRAMES.run with the
     run's totals (steps, wall_s from LAMMPS's "Loop time", particles).
The run goes to t_max: MACHDYN has no test of our contact to stop on; peer_rings --action measure cuts the frames at
run_rings's stop (run_after_contact after separation). What MACHDYN cannot do as we do is in lammps_rings.in's header.
--no-frames (make bench-peer): no frame but the first (the timing is then the stepping's); --ranks N runs lmp on N MPI
ranks (mpirun; Debian's liblammps is built with Open MPI).
Usage: lammps_rings.py --layout DIR --frames FILE --work DIR [--art-stress EPS] [--max-steps N] [--no-frames] [--ranks N] [--lmp lmp]
"""
import argparse
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import peer_io  # noqa: E402


def fail(msg):
    sys.exit(f"lammps_rings: {msg}")


def write_data(path, layout, s):
    dp, h = s["dp"], s["h"]
    xs = [float(r["x"]) for r in layout]
    ys = [float(r["y"]) for r in layout]
    pad = 4 * s["r_outer"]  # the box shrink-wraps (boundary sm): this only has to hold the particles at the start
    with open(path, "w") as f:
        f.write("# our rings (experiments/peers/peer_rings --action layout), written by experiments/peers/lammps_rings.py\n\n")
        f.write(f"{len(layout)} atoms\n2 atom types\n\n")
        f.write(f"{min(xs) - pad!r} {max(xs) + pad!r} xlo xhi\n{min(ys) - pad!r} {max(ys) + pad!r} ylo yhi\n")
        f.write(f"{-0.5 * dp!r} {0.5 * dp!r} zlo zhi\n\nAtoms # smd\n\n")
        # id type molecule vfrac rmass radius contact_radius x0 y0 z0 x y z
        for i, r in enumerate(layout):
            ring = int(float(r["ring"]))
            x, y = float(r["x"]), float(r["y"])
            f.write(f"{i + 1} {ring + 1} {ring + 1} {dp * dp!r} {float(r['m'])!r} {h!r} {0.5 * dp!r} {x!r} {y!r} 0 {x!r} {y!r} 0\n")
        f.write("\nVelocities\n\n")
        for i, r in enumerate(layout):
            f.write(f"{i + 1} {float(r['u'])!r} {float(r['v'])!r} 0\n")


def sample_steps(dt, sample_dt, t_max, max_steps):
    """Our run's samples (sph::Cadence over t accumulated as our solver does) -> ({step: t}, steps to run)."""
    t, nxt, n, samples = 0.0, sample_dt, 0, {0: 0.0}
    while t < t_max - 1e-12 and (max_steps < 0 or n < max_steps):
        t += dt
        n += 1
        if t >= nxt - 1e-12:
            samples[n] = t
            nxt += sample_dt
    return samples, n


def convert(dump, samples, frames, meta):
    w = peer_io.FrameWriter(frames, [], meta)
    count = 0
    with open(dump) as f:
        lines = iter(f)
        for line in lines:
            if not line.startswith("ITEM: TIMESTEP"):
                continue
            step = int(next(lines))
            if step not in samples:
                fail(f"{dump}: a frame at step {step}, not a sample step of ours")
            next(lines)  # ITEM: NUMBER OF ATOMS
            n = int(next(lines))
            header = ""
            while not header.startswith("ITEM: ATOMS"):
                header = next(lines)
            if header.split()[2:] != ["id", "x", "y", "vx", "vy"]:
                fail(f"{dump}: columns {header.split()[2:]}, expected id x y vx vy")
            ids, x, y, u, v = [], [], [], [], []
            for _ in range(n):
                c = next(lines).split()
                ids.append(int(c[0]) - 1)
                x.append(float(c[1]))
                y.append(float(c[2]))
                u.append(float(c[3]))
                v.append(float(c[4]))
            w.ids = ids
            w.frame(samples[step], x, y, u, v)
            count += 1
    w.close()
    return count


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--layout", required=True)
    ap.add_argument("--frames", required=True)
    ap.add_argument("--work", required=True, help="folder for the data file, the dump and LAMMPS's log")
    ap.add_argument("--art-stress", type=float, default=0.0, help="smd/ulsph *ARTIFICIAL_STRESS (0: off)")
    ap.add_argument("--max-steps", type=int, default=-1, help="stop after this many steps (quick runs)")
    ap.add_argument("--no-frames", action="store_true", help="dump only the first frame (timing runs)")
    ap.add_argument("--ranks", type=int, default=1, help="MPI ranks (mpirun -np N)")
    ap.add_argument("--lmp", default="lmp")
    a = ap.parse_args()
    if a.ranks < 1:
        fail("--ranks must be >= 1")
    a.work, a.frames = os.path.abspath(a.work), os.path.abspath(a.frames)  # lmp runs in the repository root
    s = peer_io.settings(a.layout)
    layout = peer_io.read_table(os.path.join(a.layout, "layout.csv"))
    if len(layout) != int(s["particles"]):
        fail(f"layout.csv has {len(layout)} particles, settings.csv {s['particles']:g}")
    if a.art_stress < 0:
        fail("--art-stress must be >= 0")
    os.makedirs(a.work, exist_ok=True)
    data, dump, steps_file, log = (os.path.join(a.work, n) for n in ("rings.data", "rings.dump", "sample_steps.txt", "log.lammps"))
    write_data(data, layout, s)
    samples, steps = sample_steps(s["dt"], s["sample_dt"], s["t_max"], a.max_steps)
    if a.no_frames:
        samples = {0: 0.0}
    with open(steps_file, "w") as f:
        later = sorted(k for k in samples if k > 0)
        f.write("\n".join(str(k) for k in later) + f"\n{steps + 10**9}\n")  # a last entry beyond the run
    mpi = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(a.ranks)] if a.ranks > 1 else []
    cmd = mpi + [a.lmp, "-in", os.path.join("tools", "peers", "lammps_rings.in"), "-log", log, "-screen", "none",
           "-var", "data", data, "-var", "dump", dump, "-var", "sample_steps", steps_file, "-var", "dp", repr(s["dp"]), "-var", "h", repr(s["h"]),
           "-var", "rho0", repr(s["rho0"]), "-var", "c0", repr(s["c0"]), "-var", "G", repr(s["mu"]),
           "-var", "alpha", repr(s["alpha"]), "-var", "art_stress", repr(a.art_stress), "-var", "dt", repr(s["dt"]),
           "-var", "steps", str(steps), "-var", "machdyn_so", peer_io.machdyn_plugin()]
    t0 = time.time()
    p = subprocess.run(cmd, cwd=ROOT)
    if p.returncode != 0:
        fail(f"lmp exit code {p.returncode} (log {log})")
    elapsed = time.time() - t0
    with open(log) as f:
        text = f.read()
    m = re.search(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", text)
    if not m:
        fail(f"{log}: no 'Loop time' line: the run did not finish")
    version = subprocess.run(["dpkg-query", "-W", "-f", "${Version}", "lammps"], capture_output=True, text=True).stdout.strip()
    meta = {"peer": "lammps", "code_version": version or "unknown", "pair": "smd/ulsph + smd/hertz",
            "art_stress": a.art_stress, "dt": repr(s["dt"])}
    count = convert(dump, samples, a.frames, meta)
    os.remove(dump)  # converted: the frames file holds the same numbers
    with open(a.frames + ".run", "w") as f:
        peer_io.write_header(f, dict(meta, steps=m.group(3), wall_s=m.group(1), particles=m.group(4), ranks=m.group(2), frames=count,
                                     process_s=f"{elapsed:.6g}", t_last=repr(samples[max(samples)])))


if __name__ == "__main__":
    main()
