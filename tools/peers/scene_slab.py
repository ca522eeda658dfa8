"""make peers' slab under tension (Gray 2001 Sec 7.3, Figs 8-10): PySPH and LAMMPS MACHDYN on our layout, beside ours.

A case is one of the figures' runs (eps = 0: Fig 8, standard SPH; eps = 0.3: Figs 9-10) at a spacing:
build/bin/peer_slab --action layout writes our particles and settings, each peer runs them and writes every particle
every sample_dt (our frames format), peer_slab --action measure measures the frames with our functions (the
SlabMeter and summary run_slab uses, the driver's per-run values) up to where run_slab stops, and our driver
(gray2001_fig8_10_slab --runs eps --dp dp --study-dps 0, the store of runs off so that it steps) runs the same.
The peers' variants:
  PySPH (experiments/peers/pysph_slab.py): <plasticity>_<continuity>
    plasticity pysph         its hvi.VonMisesPlasticity2D as its examples place it (in the evaluation; surface
                             without s22; the integrator's stored stress never returned)
               ours          our return (materials.hpp, with S_zz) on the stored stress after each stage
               pysph_stored  its surface, on the stored stress (eps = 0.3 only: to tell the two differences apart)
               ours_eval     our surface, in the evaluation (eps = 0.3 only)
    continuity v (PySPH's) or xsph (ours: the XSPH velocity in continuity and the velocity gradient)
  LAMMPS (experiments/peers/lammps_slab.py, tools/peers/lammps_slab.in): ulsph[_art<eps>][_ourdt][_ratefix],
    smd/ulsph with *STRENGTH_LINEAR_PLASTIC G 0.03 0 and, at eps > 0, *ARTIFICIAL_STRESS eps (its own form); no XSPH;
    at LAMMPS's own time step (0.1 of its CFL step, 0.4 x ours) and, _ourdt, at ours (unstable for it: shown, not
    a reading); _ratefix: the plugin with smd/ulsph's plastic stress update divided by dt as its elastic one is
    (tools/peers/build_machdyn_ratefix.sh, built from build_machdyn.sh's objects; env MACHDYN_OBJ elsewhere).
Spacings: the production dp = 0.032 and the exploratory dp = 0.064. G-fig8's rows are checked at the paper's
dp = 0.016, 8x the particle-steps of 0.032 (4x the particles, 2x the steps): measured at 0.064 on one shared core,
PySPH ran 0.4-1.2e5 particle-steps/s and LAMMPS 2.4e5 (its step 0.4x ours), so one PySPH eps = 0.3 run is ~2-4 min
at 0.064, ~15-35 min at 0.032 and ~2-5 h at 0.016; the 0.032 cases below take ~2-3.5 h in all. Quick: dp = 0.128, a
few steps of every code path, nothing measured.
Frames are kept gzipped (frames_<code>_<variant>.csv.gz) beside the measured trace.
"""
import gzip
import math
import os
import shutil

import peer_io

NAME = "slab"
MEASURED = ["fracture_time", "first_split_time", "clumping_time", "opening_time", "opening_from_junction", "crack_x",
            "crack_from_junction", "crack_from_centre", "neck_before_fracture", "neck_before_fracture_over_dp",
            "neck_10dp_time", "neck_at_t542", "onset_time", "onset_strain", "strain_at_fracture", "strain_at_t394",
            "pieces_at_t394"]
RUN_COLUMNS = ["case", "code", "variant", "version", "eps", "dp", "particles", "dt", "steps", "wall_s",
               "particle_steps_per_s", "force_evals_per_step"] + MEASURED + ["t_last", "complete", "blow_up"]
# The run columns that hold a G-fig8 row's quantity (reference/G-fig8.csv), per figure run.
G_FIG8 = {0.0: {"eps0_fracture_time": "fracture_time", "eps0_opening_from_junction": "opening_from_junction",
                "eps0_clumping_time": "clumping_time", "eps0_opening_time": "opening_time",
                "eps0_first_split_time": "first_split_time"},
          0.3: {"strain_at_t394": "strain_at_t394", "eps0.3_pieces_at_t394": "pieces_at_t394",
                "eps0.3_fracture_time": "fracture_time", "eps0.3_onset_strain": "onset_strain",
                "eps0.3_neck_before_fracture": "neck_before_fracture", "eps0.3_neck_10dp_time": "neck_10dp_time",
                "eps0.3_neck_at_t542": "neck_at_t542", "eps0.3_crack_from_centre": "crack_from_centre",
                "eps0.3_clumping_time": "clumping_time"}}
# slab_run_values' names (the driver's values file and peer_slab's) -> run columns.
VALUE_COLUMNS = {0.0: {}, 0.3: {"strain_at_t394": "strain_at_t394", "eps0.3_pieces_at_t394": "pieces_at_t394",
                                 "eps0.3_neck_10dp_time": "neck_10dp_time", "eps0.3_neck_at_t542": "neck_at_t542",
                                 "eps0.3_crack_from_centre": "crack_from_centre"}}
SUMMARY_COLUMNS = ["clumping_time", "first_split_time", "fracture_time", "crack_x", "crack_from_junction", "opening_time",
                   "opening_from_junction", "neck_before_fracture", "neck_before_fracture_over_dp", "onset_time",
                   "onset_strain", "strain_at_fracture"]
# Exploratory (dp = 0.064): every variant. Production (dp = 0.032, 8x the particle-steps): PySPH's own reading
# (pysph_v) and our equations in PySPH (ours_xsph), both eps (at 0.064 plasticity did not act before the eps = 0
# parting: pysph_v = ours_v and pysph_xsph = ours_xsph there); the mixed variants, the two separating ones and LAMMPS
# at our (unstable) time step only at 0.064 (CHOSEN for make peers' run time: each PySPH run at 0.032 is 15-35 min).
PYSPH_FULL = {0.0: ["pysph_v", "pysph_xsph", "ours_v", "ours_xsph"],
              0.3: ["pysph_v", "pysph_xsph", "ours_v", "ours_xsph", "pysph_stored_xsph", "ours_eval_xsph"]}
PYSPH_PRODUCTION = {0.0: ["pysph_v", "ours_xsph"], 0.3: ["pysph_v", "ours_xsph"]}
PYSPH_QUICK = {0.0: ["pysph_v", "ours_xsph"], 0.3: ["pysph_stored_v", "ours_eval_xsph"]}
# LAMMPS's runs (time step, plugin): its own time step (0.1 x smd/ulsph's CFL step 2 h / c_L, the MACHDYN examples'
# safety factor; 0.4 x ours) with the stock plugin and with the plastic update's rate divided by dt
# (tools/peers/build_machdyn_ratefix.sh says why); and ours (0.5 h / (c_L + v_end)), at which smd/ulsph's velocity
# Verlet is unstable from the start at dp = 0.064 (shown, not a reading of the scene).
LAMMPS_VARIANTS = [("lammps", "stock"), ("lammps", "ratefix"), ("ours", "stock")]
PLUGINS = {"stock": "machdynplugin.so", "ratefix": "machdynplugin_ratefix.so"}
EXPLORE_DP, PRODUCTION_DP, QUICK_DP = 0.064, 0.032, 0.128


def cases(quick):
    if quick:
        return [(eps, QUICK_DP, PYSPH_QUICK[eps]) for eps in (0.0, 0.3)]
    return [(eps, EXPLORE_DP, PYSPH_FULL[eps]) for eps in (0.0, 0.3)] + \
        [(eps, PRODUCTION_DP, PYSPH_PRODUCTION[eps]) for eps in (0.0, 0.3)]


def case_name(case):
    eps, dp, _ = case
    return f"eps{eps:g}_dp{dp:g}"


def published(root):
    """G-fig8's published values by quantity, read from reference/G-fig8.csv (their sources are there)."""
    return {r["quantity"]: float(r["published"]) for r in peer_io.read_table(os.path.join(root, "reference", "G-fig8.csv"))
            if r["published"] not in ("", None)}


def measured_row(eps, values_path, summary_path):
    """The run columns from a values file and a summary.csv, both written by our functions (slab_run_values, the
    driver's summary row): the driver's for ours, peer_slab's for a peer."""
    v = peer_io.values(values_path)
    summary = peer_io.read_table(summary_path)
    srow = next(r for r in summary if math.isclose(float(r["eps"]), eps, abs_tol=1e-12))
    out = {c: float(srow[c]) for c in SUMMARY_COLUMNS}
    for name, col in VALUE_COLUMNS[eps].items():
        out[col] = v[name]
    return out


def gzip_file(path):
    with open(path, "rb") as f, gzip.open(path + ".gz", "wb") as g:
        shutil.copyfileobj(f, g)
    os.remove(path)


def check_measurement_path(ctx, eps, dp, ours_dir, d):
    """Our own run's frames (the driver's frames_<run>.csv, one at every sample in quick mode) measured by peer_slab
    --action measure must give the driver's trace column for column (the energies aside, which need the solver): the
    path every peer's frames take is the one our driver measures with."""
    tag = "eps0.3" if eps > 0 else "eps0"
    rows = peer_io.read_table(os.path.join(ours_dir, f"frames_{tag}.csv"))
    frames = os.path.join(d, "frames_ours.csv")
    with open(frames, "w") as f:
        f.write("t,id,x,y,u,v\n")
        last, i = None, 0
        for r in rows:
            i = 0 if r["t"] != last else i + 1
            last = r["t"]
            f.write(f"{r['t']},{i},{r['x']},{r['y']},0,0\n")
    measured = os.path.join(d, "measured_ours")
    os.makedirs(measured, exist_ok=True)
    ctx.run([ctx.bin("peer_slab"), "--action", "measure", "--frames", frames, "--out", measured, "--dp", repr(dp),
             "--eps", repr(eps)], os.path.join(measured, "measure.log"))
    ours = peer_io.read_table(os.path.join(ours_dir, f"trace_{tag}.csv"))
    peer = peer_io.read_table(os.path.join(measured, "trace.csv"))
    cols = [c for c in ours[0] if c not in ("kinetic", "elastic")]
    if len(ours) != len(peer) or any(a[c] != b[c] for a, b in zip(ours, peer) for c in cols):
        raise RuntimeError(f"scene_slab: peer_slab's measure of our own frames differs from the driver's trace ({measured})")
    os.remove(frames)


def run_case(ctx, case, d):
    eps, dp, pysph_variants = case
    common = ["--dp", repr(dp), "--eps", repr(eps)]
    layout = os.path.join(d, "layout")
    os.makedirs(layout, exist_ok=True)
    ctx.run([ctx.bin("peer_slab"), "--action", "layout", "--out", layout] + common, os.path.join(d, "layout.log"))
    s = peer_io.settings(layout)
    base = dict(case=case_name(case), eps=eps, dp=dp, dt=s["dt"])
    nan = float("nan")
    # Ours: the figures' driver, one run (--runs eps) at this spacing without the resolution study.
    ours_dir = os.path.join(d, "ours")
    os.makedirs(ours_dir, exist_ok=True)
    cmd = [ctx.bin("gray2001_fig8_10_slab"), "--dp", repr(dp), "--runs", repr(eps), "--study-dps", "0", "--out", ours_dir]
    if ctx.quick:  # a frame at every sample, for the check of the measurement path below
        cmd += ["--t-max", "2", "--t-max-eps0", "2", "--frame-every", "2", "--frame-every-eps0", "2"]
    ctx.run(cmd, os.path.join(ours_dir, "run.log"))
    if ctx.quick:
        check_measurement_path(ctx, eps, dp, ours_dir, d)
    ssum = next(r for r in peer_io.read_table(os.path.join(ours_dir, "summary.csv")) if math.isclose(float(r["eps"]), eps))
    ours = dict(base, code="ours", variant="ours",
                version=peer_io.header(os.path.join(ours_dir, "summary.csv")).get("code_version", ""),
                particles=int(float(ssum["particles"])), steps=int(float(ssum["steps"])), wall_s=float(ssum["wall_s"]),
                force_evals_per_step=2, blow_up=ssum.get("blow_up", "") or "none",
                **measured_row(eps, os.path.join(ours_dir, "values_gray2001_fig8_10_slab.csv"), os.path.join(ours_dir, "summary.csv")))
    ours["t_last"] = nan
    ours["complete"] = 1
    if ctx.quick:  # a few steps: nothing is measured
        for c in MEASURED:
            ours[c] = nan
    rows = [ours]

    def measure(code, variant, frames, info, force_evals, version):
        measured = os.path.join(d, f"measured_{code}_{variant}")
        os.makedirs(measured, exist_ok=True)
        ctx.run([ctx.bin("peer_slab"), "--action", "measure", "--frames", frames, "--out", measured] + common,
                os.path.join(measured, "measure.log"))
        gzip_file(frames)
        facts = {r["name"]: r["value"] for r in peer_io.read_table(info)}
        v = peer_io.values(os.path.join(measured, "values_peer_slab.csv"))
        row = dict(base, code=code, variant=variant, version=version, particles=int(facts["particles"]),
                   dt=float(facts.get("dt", s["dt"])),
                   steps=int(facts["steps"]), wall_s=float(facts["wall_s"]), force_evals_per_step=force_evals,
                   blow_up=facts.get("blow_up", "none"), t_last=v["t_last"], complete=int(v["complete"]),
                   **measured_row(eps, os.path.join(measured, "values_peer_slab.csv"), os.path.join(measured, "summary.csv")))
        if ctx.quick:  # a few steps: nothing is measured
            for c in MEASURED:
                row[c] = nan
        return row

    version = ctx.version("pysph")
    for variant in pysph_variants:
        plasticity, _, continuity = variant.rpartition("_")
        frames, info = os.path.join(d, f"frames_pysph_{variant}.csv"), os.path.join(d, f"info_pysph_{variant}.csv")
        cmd = [ctx.py, os.path.join(ctx.root, "experiments", "peers", "pysph_slab.py"), "--layout", layout,
               "--frames", frames, "--info", info, "--plasticity", plasticity, "--continuity", continuity,
               "--disable-output", "-d", os.path.join(d, f"pysph_{variant}")]
        if ctx.threads > 1:
            cmd.append("--openmp")
        if ctx.quick:
            cmd += ["--max-steps", "30"]  # past t = 2 at dp = 0.128: two frames
        ctx.run(cmd, os.path.join(d, f"pysph_{variant}.log"))
        rows.append(measure("pysph", variant, frames, info, 2, version))
    ctx.run([os.path.join(ctx.root, "tools", "peers", "build_machdyn_ratefix.sh")], os.path.join(d, "build_ratefix.log"))
    for dt_rule, plugin in LAMMPS_VARIANTS:
        if dt_rule == "ours" and dp < EXPLORE_DP:
            continue  # unstable for smd/ulsph at 0.064 already: shown there only
        variant = (f"ulsph_art{eps:g}" if eps > 0 else "ulsph") + ("_ourdt" if dt_rule == "ours" else "") + \
            ("_ratefix" if plugin == "ratefix" else "")
        frames, info = os.path.join(d, f"frames_lammps_{variant}.csv"), os.path.join(d, f"info_lammps_{variant}.csv")
        cmd = [ctx.py, os.path.join(ctx.root, "experiments", "peers", "lammps_slab.py"), "--layout", layout,
               "--work", os.path.join(d, f"lammps_{variant}"), "--frames", frames, "--info", info, "--dt", dt_rule,
               "--machdyn-so", os.path.join(os.path.dirname(peer_io.machdyn_plugin()), PLUGINS[plugin])]
        if ctx.quick:
            cmd += ["--max-steps", "160"]  # past t = 2 at LAMMPS's step (0.014 at dp = 0.128): two frames
        ctx.run(cmd, os.path.join(d, f"lammps_{variant}.log"))
        rows.append(measure("lammps", variant, frames, info, 1, ctx.version("lammps") + ("+ratefix" if plugin == "ratefix" else "")))
    for r in rows:
        r["particle_steps_per_s"] = r["particles"] * r["steps"] / r["wall_s"] if r["wall_s"] > 0 else nan
    return rows


def compare(rows):
    from run_peers import num, ratio
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    pub = published(root)
    ours = {(r["case"]): r for r in rows if r["code"] == "ours"}
    out = []
    for r in rows:
        if r["code"] == "ours" or r["case"] not in ours:
            continue
        o = ours[r["case"]]
        eps = num(r["eps"])
        speed = num(o["particle_steps_per_s"]) * num(o["force_evals_per_step"])
        peer_speed = num(r["particle_steps_per_s"]) * num(r["force_evals_per_step"])
        for quantity, col in G_FIG8[0.3 if eps > 0 else 0.0].items():
            out.append(dict(scene=NAME, case=r["case"], quantity=quantity, dp=r["dp"], published=pub.get(quantity, math.nan),
                            theory=math.nan, ours=o[col], code=r["code"], variant=r["variant"], peer=r[col],
                            peer_over_ours=ratio(r[col], o[col]), ours_over_theory=math.nan, peer_over_theory=math.nan,
                            ours_particle_steps_per_s=o["particle_steps_per_s"],
                            peer_particle_steps_per_s=r["particle_steps_per_s"],
                            ours_force_evals_per_step=o["force_evals_per_step"],
                            peer_force_evals_per_step=r["force_evals_per_step"],
                            ours_over_peer_per_force_eval=speed / peer_speed if peer_speed > 0 else math.nan,
                            note="our measurement (scenes::SlabMeter, summarise_slab, slab_run_values) of both; -1: never"
                                 + ("" if num(r["complete"]) == 1 else "; the peer's frames end before run_slab's stop")))
    return out
