"""Gray, Monaghan & Swift 2001's oscillating plate in LAMMPS MACHDYN (smd/tlsph or smd/ulsph), from our particles.

run(ctx, layout_dir, case_dir, variant) runs one variant on the layout that build/bin/peer_plate --action layout
wrote into layout_dir (layout.csv, settings.csv) and returns
  dict(trace=<t,y_tip csv for peer_plate --action measure>, particles, steps, wall_s, cpu_s, force_evals_per_step=1,
       dt (MACHDYN's mean step), version, variant, hg, art_stress, dt_safety)
Variants (VARIANTS):
  tlsph          pair smd/tlsph (total Lagrangian, corrected gradients), hourglass control 10 (MACHDYN's examples)
  ulsph          pair smd/ulsph as tools/peers/lammps_rings.in, with its *ARTIFICIAL_STRESS 0.3 (our eps)
  ulsph_nostress the same without artificial stress
The inputs: tools/peers/lammps_plate_{tlsph,ulsph}.in (which include lammps_plate_setup.in and lammps_plate_run.in);
every setting and its source is stated there. What is ours: the particles (positions, masses, densities, the
held ones), the initial velocity (the cantilever mode), K = 1 and mu (through our E, nu), h (MACHDYN radius = h,
support 2 h), alpha and beta (Q1, Q2), the sampling (every sample_dt) and the stop (the tip's
stop_after_crossings-th zero crossing, or t_end). What is MACHDYN's: the kernel (spiky), the integrator (velocity
Verlet, one force evaluation per step), its time step (fix smd/adjust_dt 0.1: ours is unstable in both pairs, see
DT_SAFETY), the stress update (hypo-elastic rates), the viscosity on receding pairs too, and for tlsph the
total-Lagrangian corrected gradients and hourglass control, for ulsph its own artificial stress; neither has XSPH.
run(..., max_steps=N) stops after N steps (quick mode), overrides={name: value} replaces -var settings of the variant
(diagnostics), dump_every=N writes every particle every N steps.
Bad input (a missing layout, an unknown variant, a run that stops before its first sample) raises with one line.
"""
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "experiments", "peers"))
import peer_io  # noqa: E402

# The time step of every variant: MACHDYN's own, fix smd/adjust_dt 0.1 (the safety factor of all its examples):
# 0.1 x 2 radius / c_p = 0.3 dp / c_L, where ours is 0.5 h / (c_L + V_f) = 0.75 dp / (c_L + V_f), 2.5 times more.
# At ours (measured at dp = 0.4, H = 2, V_f = 0.01, mu = 0.22) smd/ulsph breaks the plate up within 500 steps (at
# half ours it holds, T as at 0.1 to 1e-4), and smd/tlsph's period is 1.0% short (0.9 ours: 0.8%) of a plateau from
# 0.75 ours down (0.75, 0.5, 0.25 ours and adjust_dt 0.1 agree within 2e-4): a bounded parasitic mode of its
# hourglass springs, not a smooth step error.
DT_SAFETY = 0.1
VARIANTS = {
    # name: (input, -var settings beyond the layout's); None: our eps_artificial
    "tlsph": ("lammps_plate_tlsph.in", {"hg": 10.0, "dt_safety": DT_SAFETY}),  # hg 10: every MACHDYN tlsph example
    "ulsph": ("lammps_plate_ulsph.in", {"art_stress": None, "dt_safety": DT_SAFETY}),
    "ulsph_nostress": ("lammps_plate_ulsph.in", {"art_stress": 0.0, "dt_safety": DT_SAFETY}),
    # diagnostics (not in make peers' cases): without hourglass control; at our fixed step
    "tlsph_hg0": ("lammps_plate_tlsph.in", {"hg": 0.0, "dt_safety": DT_SAFETY}),
    "tlsph_ourdt": ("lammps_plate_tlsph.in", {"hg": 10.0, "dt_safety": 0.0}),
}
LMP = "lmp"


def id_ranges(ids):
    """Sorted integer ids as LAMMPS id ranges 'a:b' (a single id as 'a')."""
    out, start, prev = [], None, None
    for i in sorted(ids):
        if start is None:
            start = prev = i
        elif i == prev + 1:
            prev = i
        else:
            out.append(f"{start}:{prev}" if prev > start else f"{start}")
            start = prev = i
    if start is not None:
        out.append(f"{start}:{prev}" if prev > start else f"{start}")
    return out


def write_data(path, layout, s):
    """Our layout as a LAMMPS atom_style smd data file: id = row + 1, type 1, molecule 1, vfrac = m / rho,
    rmass = m, radius = h (support radius_i + radius_j = 2 h), contact radius dp / 2; velocities ours."""
    x = [float(r["x"]) for r in layout]
    y = [float(r["y"]) for r in layout]
    pad = 2 * s["h"]
    with open(path, "w") as f:
        f.write("# our plate layout (build/bin/peer_plate --action layout), written by tools/peers/lammps_plate.py\n\n")
        f.write(f"{len(layout)} atoms\n1 atom types\n\n")
        f.write(f"{min(x) - pad!r} {max(x) + pad!r} xlo xhi\n{min(y) - pad!r} {max(y) + pad!r} ylo yhi\n")
        f.write(f"{-0.5 * s['dp']!r} {0.5 * s['dp']!r} zlo zhi\n\nAtoms # smd\n\n")
        for i, r in enumerate(layout):
            m, rho = float(r["m"]), float(r["rho"])
            f.write(f"{i + 1} 1 1 {m / rho!r} {m!r} {s['h']!r} {0.5 * s['dp']!r} {r['x']} {r['y']} 0 {r['x']} {r['y']} 0\n")
        f.write("\nVelocities\n\n")
        for i, r in enumerate(layout):
            f.write(f"{i + 1} {r['u']} {r['v']} 0\n")


def loop_stats(log):
    """(wall s, cpu s, steps, atoms, t at the end) from LAMMPS's log: its last 'Loop time of T on P procs for N steps
    with M atoms' and 'C% CPU use' lines and the input's 'PLATE_DONE: ... t = T' line (or 'DONE ... t = T')."""
    found, cpu, t_end = None, None, None
    with open(log) as f:
        for line in f:
            m = re.match(r"Loop time of (\S+) on \d+ procs for (\d+) steps with (\d+) atoms", line)
            if m:
                found = (float(m.group(1)), int(m.group(2)), int(m.group(3)))
            m = re.match(r"\s*(\S+)% CPU use", line)
            if m:
                cpu = float(m.group(1)) / 100
            m = re.match(r"\w+_DONE: .*\bt = (\S+?),", line)
            if m:
                t_end = float(m.group(1))
    if found is None or t_end is None:
        raise RuntimeError(f"lammps: no 'Loop time' or '_DONE' line in {log}: the run did not finish")
    wall, steps, atoms = found
    return wall, wall * cpu if cpu is not None else float("nan"), steps, atoms, t_end


def run(ctx, layout_dir, case_dir, variant, max_steps=None, dump_every=0, overrides=None):
    if variant not in VARIANTS:
        raise ValueError(f"lammps_plate: unknown variant '{variant}' (known: {', '.join(VARIANTS)})")
    for name in ("layout.csv", "settings.csv"):
        if not os.path.exists(os.path.join(layout_dir, name)):
            raise FileNotFoundError(f"lammps_plate: {os.path.join(layout_dir, name)} missing (peer_plate --action layout)")
    s = peer_io.settings(layout_dir)
    layout = peer_io.read_table(os.path.join(layout_dir, "layout.csv"))
    tips = [i for i, r in enumerate(layout) if float(r["tip"]) > 0.5]
    if len(tips) != 1:
        raise ValueError(f"lammps_plate: layout.csv has {len(tips)} tip particles, not 1")
    tip = tips[0]
    held = [i + 1 for i, r in enumerate(layout) if float(r["fixed"]) > 0.5]
    if not held:
        raise ValueError("lammps_plate: layout.csv has no held (fixed = 1) particles")
    work = os.path.join(case_dir, f"lammps_{variant}")
    os.makedirs(work, exist_ok=True)
    data, groups = os.path.join(work, "plate.data"), os.path.join(work, "groups.in")
    write_data(data, layout, s)
    with open(groups, "w") as f:
        ranges = id_ranges(held)
        for k in range(0, len(ranges), 50):  # LAMMPS group lines of at most 50 ranges
            f.write("group held id " + " ".join(ranges[k:k + 50]) + "\n")
    infile, extra = VARIANTS[variant]
    extra = dict(extra, **(overrides or {}))
    # The run ends at the stop crossing or at t_end (the Python function in lammps_plate_run.in); the step count
    # only bounds it: t_end / dt at our step, 20 times that with MACHDYN's (its step is ~0.4 of ours).
    nsteps = int(math.ceil(s["t_end"] / s["dt"] - 1e-9)) * (20 if extra.get("dt_safety", 0) > 0 else 1) + 10
    if max_steps is not None:
        nsteps = min(nsteps, max_steps)
    raw = os.path.join(work, "trace_raw.csv")
    v = {"peers": HERE, "machdyn_so": peer_io.machdyn_plugin(),
         "data": data, "groups": groups, "skin": s["h"], "dt": repr(s["dt"]), "h": repr(s["h"]),
         "rho0": repr(s["rho0"]), "c0": repr(s["c0"]), "E": repr(s["E"]), "nu": repr(s["nu"]), "mu": repr(s["mu"]),
         "q1": repr(s["alpha"]), "q2": repr(s["beta"]), "tip": tip + 1, "y0": layout[tip]["y"],
         "sample_dt": repr(s["sample_dt"]), "stop_after": int(s["stop_after_crossings"]), "t_end": repr(s["t_end"]),
         "trace": raw,
         "nsteps": nsteps, "thermo_every": max(1, nsteps // 20), "dump_every": dump_every}
    for k, val in extra.items():
        v[k] = repr(s["eps_artificial"] if val is None else float(val))
    if not os.path.exists(v["machdyn_so"]):
        raise FileNotFoundError(f"lammps_plate: {v['machdyn_so']} missing (tools/peers/build_machdyn.sh)")
    log = os.path.join(work, "log.lammps")
    cmd = [LMP, "-nocite", "-in", os.path.join(HERE, infile), "-log", log]
    for k, val in v.items():
        cmd += ["-var", k, str(val)]
    ctx.run(cmd, os.path.join(work, "screen.log"))
    wall, cpu, steps, atoms, t_last = loop_stats(log)
    dt = s["dt"] if extra.get("dt_safety", 0) == 0 else t_last / max(steps, 1)  # MACHDYN's: its mean step
    samples = peer_io.read_table(raw)
    if len(samples) < 2 and max_steps is None:
        raise RuntimeError(f"lammps_plate: {raw} has {len(samples)} samples: the run stopped before its first sample")
    trace = os.path.join(case_dir, f"trace_lammps_{variant}.csv")
    meta = {"peer": "lammps", "variant": variant, "input": infile, "steps": steps, "wall_s": f"{wall:.6g}",
            "cpu_s": f"{cpu:.6g}", "particles": atoms, "dt": repr(dt)}
    meta.update({f"var_{k}": v[k] for k in ("hg", "art_stress", "dt_safety", "q1", "q2", "E", "nu", "h") if k in v})
    with open(trace, "w") as f:
        peer_io.write_header(f, meta)
        f.write("t,y_tip\n")
        for r in samples:
            f.write(f"{r['t']},{r['y_tip']}\n")
    return dict(trace=trace, particles=atoms, steps=steps, wall_s=wall, cpu_s=cpu, force_evals_per_step=1, dt=dt,
                version=ctx.version("lammps"), variant=variant, hg=v.get("hg", ""), art_stress=v.get("art_stress", ""),
                dt_safety=v.get("dt_safety", ""))
