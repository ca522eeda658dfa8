"""make peers' colliding rubber rings (Gray 2001 Sec 7.2, Figs 6-7): PySPH and LAMMPS MACHDYN on our layout, beside ours.

A case is one eps of the artificial stress (0: Fig 6, the rings fracture; 0.3: Fig 7, they bounce) at a spacing:
build/bin/peer_rings --action layout writes our particles and settings (the driver's: gap 2 dp, i.e. the driver's
0.2 at the paper's dp = 0.1 and its --quick 0.4 at dp = 0.2, so the closest particles start 4 dp apart, outside the
3 dp support), each peer runs them and writes frames of every particle at our sample cadence, peer_rings --action
measure measures each with the code run_rings measures with (rings_measure.hpp), and our driver
gray2001_fig6_7_rings runs the same rings at the same spacing (both eps; the case's row is read). The eps = 0 runs
go as far as our driver's eps = 0 run (to the end of its eps = 0.3 run), read from its trace. The codes:
  ours     gray2001_fig6_7_rings --dp --gap (--coarse-check false)
  pysph    ElasticSolidsScheme (experiments/peers/pysph_rings.py), our dt fixed, run_rings's stop; variants
           v     PySPH's own continuity and velocity gradient (of v)
           xsph  those of the XSPH velocity (3.6), as ours: then only the integrator and the code differ
  lammps   MACHDYN smd/ulsph + smd/hertz contact (experiments/peers/lammps_rings.py, tools/peers/lammps_rings.in),
           our dt fixed, to t_max; variant no_art_stress (eps = 0) or art_stress_0.3 (eps = 0.3, its own form)
The cases: eps 0.3 and 0 at dp = 0.2 (1094 particles) and the paper's dp = 0.1 (4406). The paper gives no numbers for
this test (reference/G-fig6.csv has its claims): the published column is empty.
The frames files are deleted once measured (about 80 MB a run at dp = 0.1): the measured trace (trace.csv of
measured_<code>_<variant>/, the columns of our driver's trace) stays.
"""
import math
import os

import peer_io

NAME = "rings"
MEASURED = ["restitution", "contact_start", "contact_end", "contact_duration", "max_fragments", "min_main_share",
            "max_stray", "fracture_time", "t_last"]
RUN_COLUMNS = ["case", "code", "variant", "version", "eps", "dp", "particles", "dt", "steps", "wall_s",
               "particle_steps_per_s", "force_evals_per_step"] + MEASURED
COMPARED = ["restitution", "contact_duration", "max_fragments", "min_main_share", "fracture_time"]
PYSPH_VARIANTS = ["v", "xsph"]
QUICK_STEPS = 30
QUICK_DP = 0.4


def cases(quick):
    if quick:
        return [(0.3, QUICK_DP), (0.0, QUICK_DP)]
    return [(eps, dp) for dp in (0.2, 0.1) for eps in (0.3, 0.0)]


def case_name(case):
    eps, dp = case
    return f"eps{eps:g}_dp{dp:g}"


def lammps_variant(eps):
    return "no_art_stress" if eps == 0 else f"art_stress_{eps:g}"


def run_case(ctx, case, d):
    eps, dp = case
    tag = f"eps{eps:g}"
    gap = 2 * dp
    # Ours first: the driver at this spacing and gap (both eps; this case's row is read).
    ours_dir = os.path.join(d, "ours")
    os.makedirs(ours_dir, exist_ok=True)
    cmd = [ctx.bin("gray2001_fig6_7_rings"), "--dp", repr(dp), "--gap", repr(gap), "--coarse-check", "false",
           "--out", ours_dir]
    if ctx.quick:
        cmd += ["--t-max", "4"]
    ctx.run(cmd, os.path.join(ours_dir, "run.log"))
    summary = os.path.join(ours_dir, "summary.csv")
    o = [r for r in peer_io.read_table(summary) if float(r["eps"]) == eps and float(r["dp"]) == dp]
    if len(o) != 1:
        raise RuntimeError(f"{summary}: no single row for eps {eps:g}, dp {dp:g}")
    o = o[0]
    trace = peer_io.read_table(os.path.join(ours_dir, f"trace_{tag}.csv"))
    t_last_ours = trace[-1]["t"]
    # Our layout and settings; the eps = 0 runs to where our eps = 0 run stopped, as the driver runs it.
    common = ["--dp", repr(dp), "--gap", repr(gap), "--eps", repr(eps)]
    if eps == 0:
        common += ["--t-max", t_last_ours, "--after-contact", "-1"]
    layout = os.path.join(d, "layout")
    os.makedirs(layout, exist_ok=True)
    ctx.run([ctx.bin("peer_rings"), "--action", "layout", "--out", layout] + common, os.path.join(d, "layout.log"))
    s = peer_io.settings(layout)
    base = dict(case=case_name(case), eps=eps, dp=dp, dt=s["dt"])
    nan = float("nan")
    rows = [dict(base, code="ours", variant="ours", version=peer_io.header(summary).get("code_version", ""),
                 particles=int(float(o["particles"])), steps=int(float(o["steps"])), wall_s=float(o["wall_s"]),
                 force_evals_per_step=2, t_last=float(t_last_ours),
                 **{q: (float(o[q]) if o[q] not in ("", "nan") else nan) if not ctx.quick else nan
                    for q in MEASURED if q != "t_last"})]

    def measure(code, variant, frames, version, evals):
        measured = os.path.join(d, f"measured_{code}_{variant}")
        os.makedirs(measured, exist_ok=True)
        ctx.run([ctx.bin("peer_rings"), "--action", "measure", "--frames", frames, "--out", measured] + common,
                os.path.join(measured, "measure.log"))
        m = peer_io.values(os.path.join(measured, "values_peer_rings.csv"))
        meta = peer_io.header(frames + ".run")
        os.remove(frames)
        return dict(base, code=code, variant=variant, version=version, particles=int(meta["particles"]),
                    steps=int(meta["steps"]), wall_s=float(meta["wall_s"]), force_evals_per_step=evals,
                    **{q: m[q] if not ctx.quick else nan for q in MEASURED if q != "t_last"}, t_last=m["t_last"])

    version = ctx.version("pysph")
    for variant in PYSPH_VARIANTS:
        frames = os.path.join(d, f"frames_pysph_{variant}.csv")
        cmd = [ctx.py, os.path.join(ctx.root, "experiments", "peers", "pysph_rings.py"), "--layout", layout,
               "--frames", frames, "--continuity", variant, "--disable-output", "-d", os.path.join(d, f"pysph_{variant}")]
        if ctx.threads > 1:
            cmd.append("--openmp")
        if ctx.quick:
            cmd += ["--max-steps", str(QUICK_STEPS)]
        ctx.run(cmd, os.path.join(d, f"pysph_{variant}.log"))
        rows.append(measure("pysph", variant, frames, version, 2))  # EPEC: two evaluations a step
    frames = os.path.join(d, "frames_lammps.csv")
    cmd = [ctx.py, os.path.join(ctx.root, "experiments", "peers", "lammps_rings.py"), "--layout", layout,
           "--frames", frames, "--work", os.path.join(d, "lammps"), "--art-stress", repr(eps)]
    if ctx.quick:
        cmd += ["--max-steps", str(QUICK_STEPS)]
    ctx.run(cmd, os.path.join(d, "lammps.log"))
    rows.append(measure("lammps", lammps_variant(eps), frames, ctx.version("lammps"), 1))  # velocity Verlet: one
    for r in rows:
        r["particle_steps_per_s"] = r["particles"] * r["steps"] / r["wall_s"] if r["wall_s"] > 0 else nan
    return rows


def compare(rows):
    from run_peers import num, ratio
    ours = {(num(r["eps"]), num(r["dp"])): r for r in rows if r["code"] == "ours"}
    out = []
    for r in rows:
        if r["code"] == "ours":
            continue
        o = ours.get((num(r["eps"]), num(r["dp"])))
        if o is None:
            continue
        speed = num(o["particle_steps_per_s"]) * num(o["force_evals_per_step"])
        peer_speed = num(r["particle_steps_per_s"]) * num(r["force_evals_per_step"])
        for q in COMPARED:
            out.append(dict(scene=NAME, case=r["case"], quantity=f"eps{num(r['eps']):g}_{q}", dp=r["dp"], published="",
                            theory="", ours=o[q], code=r["code"], variant=r["variant"], peer=r[q],
                            peer_over_ours=ratio(r[q], o[q]), ours_over_theory=math.nan, peer_over_theory=math.nan,
                            ours_particle_steps_per_s=o["particle_steps_per_s"],
                            peer_particle_steps_per_s=r["particle_steps_per_s"],
                            ours_force_evals_per_step=o["force_evals_per_step"],
                            peer_force_evals_per_step=r["force_evals_per_step"], ours_version=o["version"],
                            peer_version=r["version"],
                            ours_over_peer_per_force_eval=speed / peer_speed if peer_speed > 0 else math.nan,
                            note="the paper gives claims, not numbers (reference/G-fig6.csv); both measured by "
                                 "rings_measure.hpp (contact: main pieces within 2h; fragments >= 10 particles at 1.5 dp)"))
    return out
