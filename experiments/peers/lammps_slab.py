#!/usr/bin/env python3
"""Gray 2001's slab under tension with LAMMPS MACHDYN smd/ulsph (tools/peers/lammps_slab.in), from our particles.

Reads our layout (build/bin/peer_slab --action layout: layout.csv, settings.csv), writes it as a LAMMPS data file
(atom_style smd; molecule 1 free, 2 left band, 3 right band), runs Debian's lmp with the MACHDYN plugin from the
repository root at our time step for ceil(t_max / dt) steps, and converts the dump to our frames format
(experiments/peers/frames_reader.hpp: t,id,x,y,u,v, id = our layout's row = LAMMPS id - 1, t = step dt) for
peer_slab --action measure. LAMMPS cannot test the connectivity during the run, so it runs to t_max; the measure
stops reading where scenes::run_slab would have stopped (run_after_fracture after the parting).
--info gets steps, the loop's wall time (LAMMPS's 'Loop time'), particles, and the command.
--art-stress: smd/ulsph's *ARTIFICIAL_STRESS amplitude (default: our eps from settings.csv; 0 = off).
"""
import argparse
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_io  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def fail(msg):
    sys.exit(f"lammps_slab: {msg}")


def write_data(path, layout, s):
    mol = {-1: 2, 0: 1, 1: 3}
    n = len(layout)
    xs = [float(r["x"]) for r in layout]
    ys = [float(r["y"]) for r in layout]
    reach = 0.5 * s["end_accel"] * s["t_max"] ** 2 + 2.0  # the ends' travel and room (shrink-wrapped anyway)
    dp, h = s["dp"], s["h"]
    with open(path, "w") as f:
        f.write("# Gray 2001 slab from our layout.csv (experiments/peers/lammps_slab.py)\n\n")
        f.write(f"{n} atoms\n1 atom types\n\n")
        f.write(f"{min(xs) - reach!r} {max(xs) + reach!r} xlo xhi\n{min(ys) - 2.0!r} {max(ys) + 2.0!r} ylo yhi\n")
        f.write(f"{-0.5 * dp!r} {0.5 * dp!r} zlo zhi\n\nAtoms # smd\n\n")
        for i, r in enumerate(layout):
            band = int(float(r["band"]))
            if band not in mol:
                fail(f"layout row {i}: band must be -1, 0 or 1")
            if float(r["u"]) != 0.0 or float(r["v"]) != 0.0:
                fail("the slab starts at rest: a layout velocity is not zero")
            m, rho = float(r["m"]), float(r["rho"])
            x, y = float(r["x"]), float(r["y"])
            # id type molecule vfrac rmass radius contact_radius x0 y0 z0 x y z
            f.write(f"{i + 1} 1 {mol[band]} {m / rho!r} {m!r} {h!r} {0.5 * dp!r} {x!r} {y!r} 0.0 {x!r} {y!r} 0.0\n")


def convert_dump(dump, frames, n, dt, meta):
    """LAMMPS dump custom (id x y vx vy, sorted by id) -> our frames; returns the number of frames."""
    w = peer_io.FrameWriter(frames, range(n), meta)
    count = 0
    with open(dump) as f:
        lines = iter(f)
        for line in lines:
            if not line.startswith("ITEM: TIMESTEP"):
                continue
            step = int(next(lines))
            if not next(lines).startswith("ITEM: NUMBER OF ATOMS"):
                fail(f"{dump}: unexpected dump layout")
            natoms = int(next(lines))
            if natoms != n:
                fail(f"{dump}: step {step} has {natoms} atoms, the layout {n}")
            while not next(lines).startswith("ITEM: ATOMS"):
                pass
            x, y, u, v = [0.0] * n, [0.0] * n, [0.0] * n, [0.0] * n
            seen = [False] * n
            for _ in range(n):
                p = next(lines).split()
                a = int(p[0]) - 1
                if not 0 <= a < n or seen[a]:
                    fail(f"{dump}: step {step}: bad or repeated id {p[0]}")
                seen[a] = True
                x[a], y[a], u[a], v[a] = (float(q) for q in p[1:5])
            w.frame(step * dt, x, y, u, v)
            count += 1
    w.close()
    return count


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--layout", required=True)
    ap.add_argument("--work", required=True, help="folder for the data file, dump, log")
    ap.add_argument("--frames", required=True)
    ap.add_argument("--info", required=True)
    ap.add_argument("--art-stress", type=float, default=None)
    ap.add_argument("--max-steps", type=int, default=None, help="quick: stop after this many steps")
    ap.add_argument("--lmp", default="lmp")
    ap.add_argument("--machdyn-so", default=os.path.join("build", "peers", "machdynplugin.so"),
                    help="the plugin, relative to the repository root or absolute")
    o = ap.parse_args()
    s = peer_io.settings(o.layout)
    layout = peer_io.read_table(os.path.join(o.layout, "layout.csv"))
    for k in ("dp", "h", "rho0", "c0", "mu", "yield_stress", "alpha", "end_accel", "dt", "t_max", "sample_dt",
              "eps_artificial"):
        if k not in s:
            fail(f"settings.csv has no '{k}'")
    art = s["eps_artificial"] if o.art_stress is None else o.art_stress
    if art < 0:
        fail("--art-stress must be >= 0")
    so = o.machdyn_so if os.path.isabs(o.machdyn_so) else os.path.join(ROOT, o.machdyn_so)
    if not os.path.exists(so):
        fail(f"no MACHDYN plugin at {so} (tools/peers/build_machdyn.sh builds it)")
    os.makedirs(o.work, exist_ok=True)
    data, dump, log = (os.path.abspath(os.path.join(o.work, n)) for n in ("slab.data", "slab.dump", "log.lammps"))
    write_data(data, layout, s)
    steps = math.ceil(s["t_max"] / s["dt"] - 1e-9)
    if o.max_steps is not None:
        steps = min(steps, o.max_steps)
    var = dict(data=data, dump=dump, dt=repr(s["dt"]), steps=steps, sample_dt=repr(s["sample_dt"]), rho0=repr(s["rho0"]),
               c0=repr(s["c0"]), G=repr(s["mu"]), **{"yield": repr(s["yield_stress"])}, alpha=repr(s["alpha"]),
               art_stress=repr(art), end_accel=repr(s["end_accel"]), h=repr(s["h"]), machdyn_so=so)
    cmd = [o.lmp, "-in", os.path.join("tools", "peers", "lammps_slab.in"), "-log", log, "-screen", "none"]
    for k, v in var.items():
        cmd += ["-var", k, str(v)]
    p = subprocess.run(cmd, cwd=ROOT, env=dict(os.environ, OMP_NUM_THREADS="1"))
    text = open(log).read() if os.path.exists(log) else ""
    if p.returncode != 0 or "SLAB_DONE" not in text:
        sys.stderr.write(text[-3000:])
        fail(f"lmp failed (exit {p.returncode}; log {log})")
    loop = re.search(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", text)
    if not loop:
        fail(f"{log}: no 'Loop time' line")
    meta = {"peer": "lammps smd/ulsph", "art_stress": art, "particles": len(layout), "dt": repr(s["dt"])}
    nframes = convert_dump(dump, o.frames, len(layout), s["dt"], meta)
    os.remove(dump)  # the frames hold the same numbers
    with open(o.info, "w") as f:
        f.write("name,value\n")
        for k, v in dict(peer="lammps", art_stress=art, particles=int(loop.group(3)), steps=int(loop.group(2)),
                         wall_s=loop.group(1), frames=nframes, t_end=repr(int(loop.group(2)) * s["dt"])).items():
            f.write(f"{k},{v}\n")


if __name__ == "__main__":
    main()
