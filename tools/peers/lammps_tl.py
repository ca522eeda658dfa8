"""Ismail 2009's total-Lagrangian scenes in LAMMPS MACHDYN's smd/tlsph, from our particles: the stress wave in the 2D
strip (Section 5.4.2; I-2d) and the quarter sheet with a hole (Section 5.4.4; I-hole).

run(ctx, layout_dir, case_dir, variant) runs the stress wave on the layout that build/bin/peer_tl --scene stress_wave
--action layout wrote into layout_dir (layout.csv, settings.csv, pulse.csv) and returns
  dict(trace=<t,T11_<g>_<r> csv for peer_tl --action measure>, particles, steps, wall_s, cpu_s,
       force_evals_per_step=1, dt, version, variant, hg, dt_safety)
run_hole(ctx, layout_dir, case_dir, variant) runs the sheet (peer_tl --scene hole --action layout: load.csv instead of
pulse.csv) and returns the same with trace=<t,id,T11,T22,T12: two stress frames> and history=<t,vmax>.
The inputs are tools/peers/lammps_wave.in and lammps_hole.in (every setting and its source is stated there).
Variants (VARIANTS):
  tlsph        hourglass control 10 (all MACHDYN smd/tlsph examples), MACHDYN's step (fix smd/adjust_dt 0.1)
  tlsph_hg0    without hourglass control (what the control does to the speed)
  tlsph_ourdt  at our fixed step (0.3 h / c_L, i.e. 0.3 of MACHDYN's 2 radius / c_p, three times its examples')
What is ours: the particles, the support radius, the material, the load p(t) (our SmoothedPulse, tabulated) on the
loaded edge, the held components, the gauges and the measurement (scenes::measure_wave). What is MACHDYN's: the
kernel (spiky), the corrected gradient and the free surfaces without ghosts (ours reflects ghosts across every
edge), the hourglass control, the hypo-elastic stress update and velocity Verlet.
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "experiments", "peers"))
import peer_io  # noqa: E402
from lammps_plate import LMP, id_ranges, loop_stats  # noqa: E402

DT_SAFETY = 0.1  # fix smd/adjust_dt's factor in every MACHDYN example
VARIANTS = {
    "tlsph": {"hg": 10.0, "dt_safety": DT_SAFETY},
    "tlsph_hg0": {"hg": 0.0, "dt_safety": DT_SAFETY},
    "tlsph_ourdt": {"hg": 10.0, "dt_safety": 0.0},
    # the sheet with a hole only: the whole sheet (our quarter mirrored), no symmetry planes
    "tlsph_full": {"hg": 10.0, "dt_safety": DT_SAFETY, "full": 1},
}


def write_data(path, layout, s):
    """Our particles as a LAMMPS atom_style smd data file (id = row + 1, type 1, molecule 1, vfrac = m / rho, rmass = m,
    radius = support / 2, contact radius ps / 2); velocities zero."""
    x = [float(r["x"]) for r in layout]
    y = [float(r["y"]) for r in layout]
    pad = s["support_radius"]
    with open(path, "w") as f:
        f.write("# our particles (build/bin/peer_tl --action layout), written by tools/peers/lammps_tl.py\n\n")
        f.write(f"{len(layout)} atoms\n1 atom types\n\n")
        f.write(f"{min(x) - pad!r} {max(x) + pad!r} xlo xhi\n{min(y) - pad!r} {max(y) + pad!r} ylo yhi\n")
        f.write(f"{-0.5 * s['ps']!r} {0.5 * s['ps']!r} zlo zhi\n\nAtoms # smd\n\n")
        for i, r in enumerate(layout):
            m, rho = float(r["m"]), float(r["rho"])
            f.write(f"{i + 1} 1 1 {m / rho!r} {m!r} {0.5 * s['support_radius']!r} {0.5 * s['ps']!r} "
                    f"{r['x']} {r['y']} 0 {r['x']} {r['y']} 0\n")


def mirrored(layout):
    """Our quarter sheet mirrored about x = 0 and y = 0 (the whole sheet): our rows first, then the mirror images of
    the rows off the planes; nothing held; load = +1 on x = +a, load_neg on x = -a."""
    out = [dict(r, held_x="0", held_y="0", load_neg="0") for r in layout]
    for sx, sy in ((-1, 1), (1, -1), (-1, -1)):
        for r in layout:
            x, y = float(r["x"]), float(r["y"])
            if (sx < 0 and x == 0.0) or (sy < 0 and y == 0.0):
                continue
            load = float(r["load"]) > 0.5
            out.append(dict(r, x=repr(sx * x) if x else r["x"], y=repr(sy * y) if y else r["y"], held_x="0", held_y="0",
                            load="1" if load and sx > 0 else "0", load_neg="1" if load and sx < 0 else "0", gauge="-1"))
    return out


def write_groups(path, layout):
    """LAMMPS groups of our flags: load, load_neg, held_x, held_y, gauge (an empty group is defined empty)."""
    with open(path, "w") as f:
        for name, pick in (("load", lambda r: float(r["load"]) > 0.5),
                           ("load_neg", lambda r: float(r.get("load_neg", 0)) > 0.5),
                           ("held_x", lambda r: float(r["held_x"]) > 0.5),
                           ("held_y", lambda r: float(r["held_y"]) > 0.5), ("gauge", lambda r: float(r["gauge"]) >= 0)):
            ranges = id_ranges([i + 1 for i, r in enumerate(layout) if pick(r)])
            if not ranges:
                f.write(f"group {name} empty\n")
            for k in range(0, len(ranges), 50):
                f.write(f"group {name} id " + " ".join(ranges[k:k + 50]) + "\n")


def read_records(dump, times, gauge_of_id):
    """The gauge dump (id, T11 every step) and the step times -> [(t, {gauge: T11})] in step order."""
    t_of = {0: 0.0}
    with open(times) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            step, t = line.split()
            t_of[int(step)] = float(t)
    records = []
    with open(dump) as f:
        lines = f.read().split("\n")
    k = 0
    while k < len(lines):
        if lines[k] == "ITEM: TIMESTEP":
            step = int(lines[k + 1])
            n = int(lines[k + 3])
            header = lines[k + 8].split()[2:]
            ci, cs = header.index("id"), header.index("c_S[1]")
            vals = {}
            for line in lines[k + 9:k + 9 + n]:
                cells = line.split()
                vals[gauge_of_id[int(cells[ci])]] = float(cells[cs])
            if step not in t_of:
                raise RuntimeError(f"lammps_tl: step {step} of {dump} has no time in {times}")
            records.append((t_of[step], vals))
            k += 9 + n
        else:
            k += 1
    return records


def run(ctx, layout_dir, case_dir, variant, max_steps=None, overrides=None):
    if variant not in VARIANTS:
        raise ValueError(f"lammps_tl: unknown variant '{variant}' (known: {', '.join(VARIANTS)})")
    if "full" in VARIANTS[variant]:
        raise ValueError(f"lammps_tl: variant '{variant}' is the sheet's only")
    for name in ("layout.csv", "settings.csv", "pulse.csv"):
        if not os.path.exists(os.path.join(layout_dir, name)):
            raise FileNotFoundError(f"lammps_tl: {os.path.join(layout_dir, name)} missing (peer_tl --action layout)")
    s = peer_io.settings(layout_dir)
    layout = peer_io.read_table(os.path.join(layout_dir, "layout.csv"))
    rows = int(s["rows"])
    gauge_of_id = {i + 1: int(float(r["gauge"])) for i, r in enumerate(layout) if float(r["gauge"]) >= 0}
    if sorted(gauge_of_id.values()) != list(range(2 * rows)):
        raise ValueError(f"lammps_tl: layout.csv's gauges are not 0..{2 * rows - 1}")
    extra = dict(VARIANTS[variant], **(overrides or {}))
    work = os.path.join(case_dir, f"lammps_{variant}")
    os.makedirs(work, exist_ok=True)
    data, groups, raw = os.path.join(work, "strip.data"), os.path.join(work, "groups.in"), os.path.join(work, "records")
    write_data(data, layout, s)
    write_groups(groups, layout)
    for suffix in (".dump", ".times"):
        if os.path.exists(raw + suffix):
            os.remove(raw + suffix)
    # The run ends at t_end (fix halt); the step count only bounds it (MACHDYN's step is ~1/3 of ours).
    nsteps = int(math.ceil(s["t_end"] / s["dt"])) * (10 if extra["dt_safety"] > 0 else 1) + 10
    if max_steps is not None:
        nsteps = min(nsteps, max_steps)
    v = {"peers": HERE, "machdyn_so": peer_io.machdyn_plugin(),
         "data": data, "groups": groups, "pulse": os.path.join(layout_dir, "pulse.csv"), "trace": raw,
         "skin": repr(0.5 * s["support_radius"]), "dt": repr(s["dt"]), "ps": repr(s["ps"]), "rows": rows,
         "rho": repr(s["rho"]), "E": repr(s["E"]), "nu": repr(s["nu"]), "q1": 0.0, "q2": 0.0,
         "t_end": repr(s["t_end"]), "nsteps": nsteps, "thermo_every": max(1, nsteps // 10)}
    v.update({k: repr(float(val)) for k, val in extra.items()})
    if not os.path.exists(v["machdyn_so"]):
        raise FileNotFoundError(f"lammps_tl: {v['machdyn_so']} missing (tools/peers/build_machdyn.sh)")
    log = os.path.join(work, "log.lammps")
    cmd = [LMP, "-nocite", "-in", os.path.join(HERE, "lammps_wave.in"), "-log", log]
    for k, val in v.items():
        cmd += ["-var", k, str(val)]
    ctx.run(cmd, os.path.join(work, "screen.log"))
    wall, cpu, steps, atoms, t_last = loop_stats(log)
    dt = s["dt"] if extra["dt_safety"] == 0 else t_last / max(steps, 1)
    records = read_records(raw + ".dump", raw + ".times", gauge_of_id)
    trace = os.path.join(case_dir, f"trace_lammps_{variant}.csv")
    cols = [f"T11_{g}_{r}" for g in range(2) for r in range(rows)]
    with open(trace, "w") as f:
        peer_io.write_header(f, {"peer": "lammps", "variant": variant, "input": "lammps_wave.in", "steps": steps,
                                 "wall_s": f"{wall:.6g}", "cpu_s": f"{cpu:.6g}", "particles": atoms, "dt": repr(dt),
                                 "hg": v["hg"], "dt_safety": v["dt_safety"]})
        f.write("t," + ",".join(cols) + "\n")
        for t, vals in records:
            f.write(repr(t) + "," + ",".join(repr(vals[g * rows + r]) for g in range(2) for r in range(rows)) + "\n")
    return dict(trace=trace, particles=atoms, steps=steps, wall_s=wall, cpu_s=cpu, force_evals_per_step=1, dt=dt,
                version=ctx.version("lammps"), variant=variant, hg=float(v["hg"]), dt_safety=float(v["dt_safety"]))


def read_frame(path):
    """A LAMMPS write_dump of 'id c_S[1] c_S[2] c_S[4]' -> [(row, T11, T22, T12)] (row = id - 1)."""
    with open(path) as f:
        lines = f.read().split("\n")
    k = lines.index("ITEM: NUMBER OF ATOMS")
    n = int(lines[k + 1])
    header = lines[k + 6].split()[2:]
    ci, c11, c22, c12 = (header.index(c) for c in ("id", "c_S[1]", "c_S[2]", "c_S[4]"))
    out = []
    for line in lines[k + 7:k + 7 + n]:
        cells = line.split()
        out.append((int(cells[ci]) - 1, cells[c11], cells[c22], cells[c12]))
    return out


def run_hole(ctx, layout_dir, case_dir, variant, max_steps=None, overrides=None):
    if variant not in VARIANTS:
        raise ValueError(f"lammps_tl: unknown variant '{variant}' (known: {', '.join(VARIANTS)})")
    for name in ("layout.csv", "settings.csv", "load.csv"):
        if not os.path.exists(os.path.join(layout_dir, name)):
            raise FileNotFoundError(f"lammps_tl: {os.path.join(layout_dir, name)} missing (peer_tl --scene hole --action layout)")
    s = peer_io.settings(layout_dir)
    layout = peer_io.read_table(os.path.join(layout_dir, "layout.csv"))
    masses = {float(r["m"]) for r in layout}
    if len(masses) != 1:
        raise ValueError("lammps_tl: the sheet's particles differ in mass: fix viscous's one gamma would not be m c")
    extra = dict(VARIANTS[variant], **(overrides or {}))
    full = bool(extra.pop("full", 0))
    n_ours = len(layout)
    work = os.path.join(case_dir, f"lammps_{variant}")
    os.makedirs(work, exist_ok=True)
    data, groups, raw = os.path.join(work, "sheet.data"), os.path.join(work, "groups.in"), os.path.join(work, "records")
    particles = mirrored(layout) if full else layout
    write_data(data, particles, s)
    write_groups(groups, particles)
    for suffix in (".before.dump", ".end.dump", ".vmax"):
        if os.path.exists(raw + suffix):
            os.remove(raw + suffix)
    nsteps = int(math.ceil(s["t_end"] / s["dt"])) * (10 if extra["dt_safety"] > 0 else 1) + 10
    if max_steps is not None:
        nsteps = min(nsteps, max_steps)
    v = {"peers": HERE, "machdyn_so": peer_io.machdyn_plugin(),
         "data": data, "groups": groups, "load": os.path.join(layout_dir, "load.csv"), "trace": raw,
         "skin": repr(0.5 * s["support_radius"]), "dt": repr(s["dt"]), "ps": repr(s["ps"]),
         "rho": repr(s["rho"]), "E": repr(s["E"]), "nu": repr(s["nu"]), "q1": 0.0, "q2": 0.0,
         "gamma": repr(masses.pop() * s["damping"]), "t_before": repr(s["t_before"]), "t_end": repr(s["t_end"]),
         "nsteps": nsteps, "thermo_every": max(1, nsteps // 20)}
    v.update({k: repr(float(val)) for k, val in extra.items()})
    if not os.path.exists(v["machdyn_so"]):
        raise FileNotFoundError(f"lammps_tl: {v['machdyn_so']} missing (tools/peers/build_machdyn.sh)")
    log = os.path.join(work, "log.lammps")
    cmd = [LMP, "-nocite", "-in", os.path.join(HERE, "lammps_hole.in"), "-log", log]
    for k, val in v.items():
        cmd += ["-var", k, str(val)]
    ctx.run(cmd, os.path.join(work, "screen.log"))
    # Two runs (to the first frame, then to the end): the steps and times of both.
    walls, cpus, steps_all = [], [], 0
    import re
    cpu = None
    with open(log) as f:
        for line in f:
            m = re.match(r"Loop time of (\S+) on \d+ procs for (\d+) steps with (\d+) atoms", line)
            if m:
                walls.append(float(m.group(1)))
                steps_all += int(m.group(2))
                atoms = int(m.group(3))
            m = re.match(r"\s*(\S+)% CPU use", line)
            if m:
                cpus.append(float(m.group(1)) / 100 * walls[-1])
    _, _, _, _, t_last = loop_stats(log)
    if len(walls) != 2:
        raise RuntimeError(f"lammps_tl: {log} has {len(walls)} runs, not 2")
    wall, cpu = sum(walls), sum(cpus)
    dt = s["dt"] if extra["dt_safety"] == 0 else t_last / max(steps_all, 1)
    meta = {"peer": "lammps", "variant": variant, "input": "lammps_hole.in", "steps": steps_all, "wall_s": f"{wall:.6g}",
            "cpu_s": f"{cpu:.6g}", "particles": atoms, "dt": repr(dt), "hg": v["hg"], "dt_safety": v["dt_safety"]}
    trace = os.path.join(case_dir, f"stress_lammps_{variant}.csv")
    t_first = None
    with open(log) as f:
        for line in f:
            if line.startswith("HOLE_DONE:"):
                t_first = float(line.rsplit("=", 1)[1])
    if t_first is None:
        raise RuntimeError(f"lammps_tl: {log} has no HOLE_DONE line")
    with open(trace, "w") as f:
        peer_io.write_header(f, meta)
        f.write("t,id,T11,T22,T12\n")
        for t, frame in ((t_first, read_frame(raw + ".before.dump")), (t_last, read_frame(raw + ".end.dump"))):
            for row, a, b, c in frame:
                if row < n_ours:  # our quarter's particles (the whole sheet's others are their mirror images)
                    f.write(f"{t!r},{row},{a},{b},{c}\n")
    history = os.path.join(case_dir, f"vmax_lammps_{variant}.csv")
    with open(raw + ".vmax") as src, open(history, "w") as f:
        peer_io.write_header(f, meta)
        f.write("t,vmax\n")
        for line in src:
            if line[:1].isdigit():
                f.write(line)
    return dict(trace=trace, history=history, particles=atoms, steps=steps_all, wall_s=wall, cpu_s=cpu,
                force_evals_per_step=1, dt=dt, version=ctx.version("lammps"), variant=variant, hg=float(v["hg"]),
                dt_safety=float(v["dt_safety"]))
