#!/usr/bin/env python3
"""Gray 2001's slab under tension with LAMMPS MACHDYN smd/ulsph (tools/peers/lammps_slab.in), from our particles.

Reads our layout (build/bin/peer_slab --action layout: layout.csv, settings.csv), writes it as a LAMMPS data file
(atom_style smd; molecule 1 free, 2 left band, 3 right band), runs Debian's lmp with the MACHDYN plugin from the
repository root for ceil(t_max / dt) steps of a fixed dt (--dt: LAMMPS's own step by default, ours on request: at
ours, 0.5 h / (c_L + v_end), smd/ulsph's velocity Verlet goes unstable at once at dp = 0.064, the slab thickening
by 10% before any load), and converts the dump to our frames format (experiments/peers/frames_reader.hpp: t,id,x,y,u,v, id = our layout's row = LAMMPS id - 1, t = step dt) for
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
    """LAMMPS dump custom (id x y vx vy, sorted by id) -> our frames, up to the first frame that is incomplete or has
    a non-finite number (a run that went unstable: frames_reader.hpp refuses those). Returns (frames, why it stopped
    early or '')."""
    w = peer_io.FrameWriter(frames, range(n), meta)
    count, why = 0, ""
    with open(dump) as f:
        lines = iter(f)
        try:
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
                if not all(math.isfinite(q) for q in x + y + u + v):
                    why = f"non-finite state at step {step} (t = {step * dt:.6g})"
                    break
                w.frame(step * dt, x, y, u, v)
                count += 1
        except StopIteration:
            why = why or "the dump ends inside a frame"
    w.close()
    return count, why


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--layout", required=True)
    ap.add_argument("--work", required=True, help="folder for the data file, dump, log")
    ap.add_argument("--frames", required=True)
    ap.add_argument("--info", required=True)
    ap.add_argument("--art-stress", type=float, default=None)
    ap.add_argument("--dt", choices=["lammps", "ours"], default="lammps",
                    help="lammps: 0.1 x smd/ulsph's CFL step 2 h / c_L (the MACHDYN examples' fix smd/adjust_dt 0.1), fixed;"
                         " ours: settings.csv dt (cfl 0.5 h / (c_L + v_end): unstable for smd/ulsph at dp 0.064)")
    ap.add_argument("--max-steps", type=int, default=None, help="quick: stop after this many steps")
    ap.add_argument("--lmp", default="lmp")
    ap.add_argument("--machdyn-so", default=peer_io.machdyn_plugin(),
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
    if o.dt == "ours":
        dt = s["dt"]
    else:  # smd/ulsph's dtCFL = 2 radius / p-wave speed, radius = h, p-wave speed sqrt((K + 4 G / 3) / rho0) (elastic)
        dt = 0.1 * 2.0 * s["h"] / math.sqrt((s["rho0"] * s["c0"] ** 2 + 4.0 * s["mu"] / 3.0) / s["rho0"])
    steps = math.ceil(s["t_max"] / dt - 1e-9)
    if o.max_steps is not None:
        steps = min(steps, o.max_steps)
    var = dict(data=data, dump=dump, dt=repr(dt), steps=steps, sample_dt=repr(s["sample_dt"]), rho0=repr(s["rho0"]),
               c0=repr(s["c0"]), G=repr(s["mu"]), **{"yield": repr(s["yield_stress"])}, alpha=repr(s["alpha"]),
               art_stress=repr(art), end_accel=repr(s["end_accel"]), h=repr(s["h"]), machdyn_so=so)
    cmd = [o.lmp, "-in", os.path.join("tools", "peers", "lammps_slab.in"), "-log", log, "-screen", "none"]
    for k, v in var.items():
        cmd += ["-var", k, str(v)]
    p = subprocess.run(cmd, cwd=ROOT, env=dict(os.environ, OMP_NUM_THREADS="1"))
    text = open(log).read() if os.path.exists(log) else ""
    # A run that fails after it started stepping (a LAMMPS error from a state gone unstable) keeps its frames up to
    # there, with the failure as its blow_up; one that fails before (input, plugin) stops here.
    if "SLAB:" not in text or not os.path.exists(dump):
        sys.stderr.write(text[-3000:])
        fail(f"lmp failed before stepping (exit {p.returncode}; log {log})")
    blow_up = ""
    if p.returncode != 0 or "SLAB_DONE" not in text:
        errors = [line for line in text.splitlines() if line.startswith("ERROR")]
        blow_up = f"lmp exit {p.returncode}: " + (errors[-1] if errors else "no SLAB_DONE")
    loop = re.search(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", text)
    meta = {"peer": "lammps smd/ulsph", "art_stress": art, "particles": len(layout), "dt": repr(dt)}
    nframes, why = convert_dump(dump, o.frames, len(layout), dt, meta)
    blow_up = blow_up or why
    if nframes == 0:
        fail(f"no complete frame in {dump} ({blow_up})")
    os.remove(dump)  # the frames hold the same numbers
    steps_done = int(loop.group(2)) if loop else steps
    wall = loop.group(1) if loop else "nan"
    with open(o.info, "w") as f:
        f.write("name,value\n")
        for k, v in dict(peer="lammps", art_stress=art, dt_rule=o.dt, plugin=os.path.basename(so), particles=len(layout),
                         steps=steps_done, wall_s=wall, frames=nframes, dt=repr(dt), t_end=repr(steps_done * dt),
                         blow_up=blow_up or "none").items():
            f.write(f"{k},{v}\n")


if __name__ == "__main__":
    main()
