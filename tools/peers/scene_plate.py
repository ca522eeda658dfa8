"""make peers' plate (Gray 2001 Sec 7.1, Tables 1-2): PySPH's ElasticSolidsScheme on our layouts, beside ours.

A case is a row of Table 1 or 2 at a spacing: build/bin/peer_plate --action layout writes our particles and
settings, PySPH runs them (experiments/peers/pysph_plate.py) in each of the case's variants, peer_plate
--action measure measures each trace with our period finder, and our Table 1-2 driver runs the same row at
the same spacing. The variants:
  ours_clamp    PySPH's equations, our clamp (held particles carry stress and do not move)
  xsph_cont     the same with continuity and the velocity gradient of the XSPH velocity (3.6), as ours:
                then only the integrator and the code differ
  xsph_gray     the same with our integrator, Gray 2001's predictor-corrector (6.14)-(6.18): then only the code
                differs (on the convergence cases and on the rows whose xsph_cont rows FAILed, GRAY_ROWS)
  walls         PySPH's own example clamp (held particles a wall array with sigma = 0)
  lammps_tlsph  LAMMPS MACHDYN smd/tlsph (total Lagrangian, hourglass control), our clamp and initial mode, its own
  lammps_ulsph  step; smd/ulsph with its own artificial stress 0.3 (tools/peers/lammps_plate.py says what differs)
The cases: Table 1's three V_f = 0.01 rows and its V_f = 0.05, mu = 0.6 row at the paper's n = 20 (dp = 0.1),
Table 2's three V_f = 0.01 rows and its two open mu = 0.6 rows at the paper's dp = 0.1 (n = 10), its four rows at
V_f = 0.03, 0.05 and mu = 0.22, 0.3 (open since 2026-12-07; PySPH's own equations only, ~1.5 h of one core each), and the
convergence of Table 1's V_f = 0.01 rows over n = 5, 10, 20 (dp = 0.4, 0.2, 0.1); LAMMPS (cases of their own, named
..._lammps, ~9 min of one core per variant at dp = 0.1) on Table 1's V_f = 0.01 rows at those three spacings and Table
2's at dp = 0.1 (tlsph only there).
"""
import os

import peer_io

NAME = "plate"
RUN_COLUMNS = ["case", "code", "variant", "version", "row", "table", "H", "Vf", "mu", "dp", "particles", "dt", "steps",
               "wall_s", "particle_steps_per_s", "force_evals_per_step", "T_sph", "crossings", "tip_amplitude",
               "T_theory_reading", "T_published"]
FULL = ["ours_clamp", "xsph_cont", "walls"]
LAMMPS = ["lammps_tlsph", "lammps_ulsph"]
PEER_ARGS = {"ours_clamp": ["--clamp", "ours"], "xsph_cont": ["--clamp", "ours", "--continuity", "xsph"],
             "xsph_gray": ["--clamp", "ours", "--continuity", "xsph", "--integrator", "gray"],
             "walls": ["--clamp", "walls"]}
# The production rows that also run xsph_gray: the three whose xsph_cont rows FAILed (the integrators' difference was
# larger than predicted; with ours PySPH's period agreed with ours to 5.5-9e-15 at n = 5 and 10).
GRAY_ROWS = ("H2_Vf0.01_mu0.22", "H1_Vf0.01_mu0.22", "H1_Vf0.03_mu0.6")


def published(root):
    """The published T_sph of every row, read from reference/G-tab1.csv and G-tab2.csv (their sources are there)."""
    out = {}
    for t in ("G-tab1", "G-tab2"):
        for r in peer_io.read_table(os.path.join(root, "reference", f"{t}.csv")):
            if r["quantity"].startswith("T_sph_H"):
                out[r["quantity"][len("T_sph_"):]] = float(r["published"])
    return out

def row_name(H, Vf, mu):
    return f"H{H:g}_Vf{Vf:g}_mu{mu:g}"


def cases(quick):
    if quick:
        return [(2.0, 0.01, 0.6, 0.5, ["ours_clamp", "xsph_gray"] + LAMMPS)]
    gray = lambda H, Vf, mu: ["xsph_gray"] if row_name(H, Vf, mu) in GRAY_ROWS else []
    t1 = [(2.0, 0.01, mu, 0.1, (FULL if mu == 0.6 else FULL[:2]) + gray(2.0, 0.01, mu)) for mu in (0.22, 0.3, 0.6)]
    t1.append((2.0, 0.05, 0.6, 0.1, FULL[:2]))
    t2 = [(1.0, 0.01, mu, 0.1, FULL[:2] + gray(1.0, 0.01, mu)) for mu in (0.22, 0.3, 0.6)]
    t2 += [(1.0, Vf, 0.6, 0.1, FULL[:2] + gray(1.0, Vf, 0.6)) for Vf in (0.03, 0.05)]
    t2 += [(1.0, Vf, mu, 0.1, FULL[:1]) for mu in (0.22, 0.3) for Vf in (0.03, 0.05)]
    conv = [(2.0, 0.01, mu, dp, FULL[:2] + ["xsph_gray"]) for mu in (0.22, 0.3, 0.6) for dp in (0.4, 0.2)]
    lmp = [(2.0, 0.01, mu, dp, LAMMPS) for mu in (0.22, 0.3, 0.6) for dp in (0.4, 0.2, 0.1)]
    lmp += [(1.0, 0.01, mu, 0.1, ["lammps_tlsph"]) for mu in (0.22, 0.3, 0.6)]  # ulsph: Table 1's rows only (run time)
    return conv + t1 + t2 + lmp


def case_name(case):
    H, Vf, mu, dp, variants = case
    lammps_only = all(v in LAMMPS for v in variants)
    return f"{row_name(H, Vf, mu)}_dp{dp:g}" + ("_lammps" if lammps_only else "")


def missing(case, rows):
    """The variants of a case that its runs.csv lacks (a variant added since the case ran)."""
    have = {r["variant"] if r["code"] == "pysph" else f"lammps_{r['variant']}" for r in rows if r["code"] != "ours"}
    return [v for v in case[4] if v not in have]


def run_case(ctx, case, d):
    H, Vf, mu, dp, variants = case
    row = row_name(H, Vf, mu)
    common = ["--dp", str(dp), "--H", str(H), "--Vf", str(Vf), "--mu", str(mu)]
    layout = os.path.join(d, "layout")
    os.makedirs(layout, exist_ok=True)
    ctx.run([ctx.bin("peer_plate"), "--action", "layout", "--out", layout] + common, os.path.join(d, "layout.log"))
    s = peer_io.settings(layout)
    # Ours first: the same row at the same spacing by its own driver.
    ours_dir = os.path.join(d, "ours")
    os.makedirs(ours_dir, exist_ok=True)
    cmd = [ctx.bin("gray2001_table1_2_plate_periods"), "--dp", str(dp), "--table", "1" if H == 2.0 else "2",
           "--rows", row, "--coarse-reference", "false", "--same-n-reading", "false", "--out", ours_dir]
    if ctx.quick:
        cmd += ["--max-steps", "30"]
    ctx.run(cmd, os.path.join(ours_dir, "run.log"))
    p = peer_io.read_table(os.path.join(ours_dir, "periods.csv"))[0]
    base = dict(case=case_name(case), row=row, table=1 if H == 2.0 else 2, H=H, Vf=Vf, mu=mu, dp=dp,
                T_theory_reading=float(p["T_theory_reading"]), T_published=published(ctx.root).get(row, float("nan")))
    rows = [dict(base, code="ours", variant="ours", version=peer_io.header(os.path.join(ours_dir, "periods.csv")).get("code_version", ""),
                 particles=int(float(p["particles"])), dt=float(p["dt"]), steps=int(float(p["steps"])),
                 wall_s=float(p["wall_s"]), force_evals_per_step=2,
                 T_sph=float(p["T_sph"]) if not ctx.quick else float("nan"), crossings=float("nan"),
                 tip_amplitude=float(p["tip_amplitude"]))]
    version = ctx.version("pysph")

    def measured(code, variant, trace):
        folder = os.path.join(d, f"measured_{code}_{variant}")
        os.makedirs(folder, exist_ok=True)
        ctx.run([ctx.bin("peer_plate"), "--action", "measure", "--trace", trace, "--out", folder] + common,
                os.path.join(folder, "measure.log"))
        return peer_io.values(os.path.join(folder, "values_peer_plate.csv"))

    for variant in (v for v in variants if v not in LAMMPS):
        trace = os.path.join(d, f"trace_pysph_{variant}.csv")
        cmd = [ctx.py, os.path.join(ctx.root, "experiments", "peers", "pysph_plate.py"), "--layout", layout,
               "--trace", trace, "--disable-output", "-d", os.path.join(d, f"pysph_{variant}")] + PEER_ARGS[variant]
        if ctx.threads > 1:
            cmd.append("--openmp")
        if ctx.quick:
            cmd += ["--max-steps", "30"]
        # A trace is written once, at the run's end: one that exists is a finished run of this case (--force reruns
        # the case in a fresh folder's place), so a make peers stopped inside a case resumes at its next run.
        if not os.path.exists(trace) or ctx.force:
            ctx.run(cmd, os.path.join(d, f"pysph_{variant}.log"))
        m = measured("pysph", variant, trace)
        meta = peer_io.header(trace)
        rows.append(dict(base, code="pysph", variant=variant, version=version, particles=int(meta["particles"]),
                         dt=s["dt"], steps=int(meta["steps"]), wall_s=float(meta["wall_s"]), force_evals_per_step=2,
                         T_sph=m["T_sph"] if not ctx.quick else float("nan"), crossings=int(m["crossings"]),
                         tip_amplitude=m["tip_amplitude"]))
    for variant in (v for v in variants if v in LAMMPS):
        import lammps_plate
        name = variant[len("lammps_"):]
        r = lammps_plate.run(ctx, layout, d, name, max_steps=30 if ctx.quick else None)
        m = measured("lammps", name, r["trace"])
        rows.append(dict(base, code="lammps", variant=name, version=r["version"], particles=r["particles"], dt=r["dt"],
                         steps=r["steps"], wall_s=r["wall_s"], force_evals_per_step=r["force_evals_per_step"],
                         T_sph=m["T_sph"] if not ctx.quick else float("nan"), crossings=int(m["crossings"]),
                         tip_amplitude=m["tip_amplitude"]))
    for r in rows:
        r["particle_steps_per_s"] = r["particles"] * r["steps"] / r["wall_s"] if r["wall_s"] > 0 else float("nan")
    return rows


def compare(rows):
    from run_peers import num, ratio
    ours = {(r["row"], num(r["dp"])): r for r in rows if r["code"] == "ours"}
    out = []
    for r in rows:
        if r["code"] == "ours":
            continue
        o = ours.get((r["row"], num(r["dp"])))
        if o is None:
            continue
        speed = num(o["particle_steps_per_s"]) * num(o["force_evals_per_step"])
        peer_speed = num(r["particle_steps_per_s"]) * num(r["force_evals_per_step"])
        out.append(dict(scene=NAME, case=r["case"], quantity=f"T_sph_{r['row']}", dp=r["dp"], published=r["T_published"],
                        theory=r["T_theory_reading"], ours=o["T_sph"], code=r["code"], variant=r["variant"],
                        peer=r["T_sph"], peer_over_ours=ratio(r["T_sph"], o["T_sph"]),
                        ours_over_theory=ratio(o["T_sph"], r["T_theory_reading"]),
                        peer_over_theory=ratio(r["T_sph"], r["T_theory_reading"]),
                        ours_particle_steps_per_s=o["particle_steps_per_s"],
                        peer_particle_steps_per_s=r["particle_steps_per_s"],
                        ours_force_evals_per_step=o["force_evals_per_step"],
                        peer_force_evals_per_step=r["force_evals_per_step"], ours_version=o["version"],
                        peer_version=r["version"],
                        ours_over_peer_per_force_eval=speed / peer_speed if peer_speed > 0 else float("nan"),
                        note="period from the tip's first zero crossing, T = 2 t_1, by our finder for both"))
    return out
