"""make peers' total-Lagrangian scenes (Ismail 2009 Section 5.4): LAMMPS MACHDYN's smd/tlsph on our particles, beside
ours (PySPH 1.0b1 has no total-Lagrangian scheme). Two scenes, each measured by our functions (build/bin/peer_tl):

stress_wave (Figs 5.7-5.9; I-2d). A case is one wave (kind stress: free sides, the thesis's stress wave; kind
strain: sides held transversely, the check of the set-up, whose speed c_L is not in question) at one resolution:
peer_tl --action layout writes our particles, settings and load pulse, LAMMPS runs them (tools/peers/lammps_tl.py,
lammps_wave.in), peer_tl --action measure measures its gauge records with scenes::measure_wave (our driver's
function), peer_tl --action ours runs our strip by scenes::run_wave_2d (our driver's run) at the same resolution.
The question (reference/I-2d.csv, wave_speed_stress, open): the thesis expects the bar speed c_b = sqrt(E/rho) =
5000 m/s; a plane-strain code (ours; MACHDYN's 2D, F33 = 1) has the plate speed sqrt(E/(rho (1 - nu^2))) = 5241.
The codes run different discretisations (ours: plain gradient, modified mollifier, ghost reflection at every edge;
MACHDYN: corrected gradient of its spiky kernel, free surfaces without ghosts, hourglass control), so both are
reported against both speeds, each at two resolutions of the same strip (six rows at the thesis's 0.5 mm, eleven
at 0.25 mm). Peer variants: tlsph (hourglass control 10, MACHDYN's own step), tlsph_hg0, tlsph_ourdt.

hole (Figs 5.13-5.15; I-hole). The quarter sheet at the thesis's 21 x 21 and at 41 x 41, run to rest; the peer's
stress field on our particles read out by scenes::hole_stress (run_hole's readout), ours by scenes::run_hole
(neo-Hookean, and Hooke as the peer's law is linear). The question (I-hole peak_sigma1_MPa, open): the thesis's
60 MPa at the hole against our 15-18 MPa. Peer variants: tlsph (symmetry planes by fix setforce, as ours holds
them), tlsph_full (the whole sheet, our quarter mirrored: no symmetry planes, at 21 x 21), tlsph_hg0.
"""
import os

import peer_io

NAME = "tl"
RUN_COLUMNS = ["case", "code", "variant", "version", "scene", "kind", "ps", "rows", "n", "particles", "dt", "steps",
               "wall_s", "cpu_s", "particle_steps_per_s", "force_evals_per_step", "hg", "dt_safety", "wave_speed",
               "plateau_over_p0", "thickness_spread_over_p0", "c_L", "c_plate", "c_bar", "peak_sigma1_MPa",
               "sigma1_hole_top_MPa", "smoothed_sigma1_hole_top_MPa", "smoothed_peak_sigma1_MPa", "settle_change",
               "rest_speed_ratio", "kirsch_MPa", "published"]
HOLE_VALUES = ("peak_sigma1_MPa", "sigma1_hole_top_MPa", "smoothed_sigma1_hole_top_MPa", "smoothed_peak_sigma1_MPa",
               "settle_change", "rest_speed_ratio", "kirsch_MPa")
QUICK_STEPS = 30


def published(root):
    """The thesis's numbers, read from reference/: I-2d.csv's wave_speed_stress and wave_speed_strain (by kind) and
    I-hole.csv's peak_sigma1_MPa (key 'hole'); their sources are there."""
    out = {r["quantity"][len("wave_speed_"):]: float(r["published"])
           for r in peer_io.read_table(os.path.join(root, "reference", "I-2d.csv"))
           if r["quantity"].startswith("wave_speed_")}
    for r in peer_io.read_table(os.path.join(root, "reference", "I-hole.csv")):
        if r["quantity"] == "peak_sigma1_MPa":
            out["hole"] = float(r["published"])
    return out


def cases(quick):
    if quick:
        return [("stress_wave", "stress", 1.5e-3, 6, ["tlsph"]), ("hole", "", 0, 11, ["tlsph", "tlsph_full"])]
    return [("stress_wave", "stress", 0.5e-3, 6, ["tlsph", "tlsph_hg0", "tlsph_ourdt"]),
            ("stress_wave", "stress", 0.25e-3, 11, ["tlsph"]),
            ("stress_wave", "strain", 0.5e-3, 6, ["tlsph"]),
            ("stress_wave", "strain", 0.25e-3, 11, ["tlsph"]),
            ("hole", "", 0, 21, ["tlsph", "tlsph_full", "tlsph_hg0"]),
            ("hole", "", 0, 41, ["tlsph"])]


def case_name(case):
    scene, kind, ps, rows, _ = case
    if scene == "hole":
        return f"hole_n{rows}"
    return f"{scene}_{kind}_ps{ps * 1e3:g}mm_rows{rows}"


def run_hole_case(ctx, case, d):
    """The sheet with a hole: rows is n (particles along a side)."""
    import lammps_tl
    scene, _, _, n, variants = case
    common = ["--scene", "hole", "--n", str(n)]
    layout = os.path.join(d, "layout")
    os.makedirs(layout, exist_ok=True)
    ctx.run([ctx.bin("peer_tl"), "--action", "layout", "--out", layout] + common, os.path.join(d, "layout.log"))
    s = peer_io.settings(layout)
    base = dict(case=case_name(case), scene=scene, kind="", ps=s["ps"], rows="", n=n,
                published=published(ctx.root).get("hole", float("nan")))

    def measures(values):
        return {k: values[k] if not ctx.quick or k == "kirsch_MPa" else float("nan") for k in HOLE_VALUES}

    out = []
    for law, flag in (("ours", "false"), ("ours_hooke", "true")):
        ours_dir = os.path.join(d, law)
        ctx.run([ctx.bin("peer_tl"), "--action", "ours", "--hooke", flag, "--out", ours_dir] +
                common, os.path.join(d, f"{law}.log"))
        o = peer_io.values(os.path.join(ours_dir, "values_peer_tl.csv"))
        out.append(dict(base, code="ours", variant=law,
                        version=peer_io.header(os.path.join(ours_dir, "values_peer_tl.csv")).get("code_version", ""),
                        particles=int(o["particles"]), dt=o["dt"], steps=int(o["steps"]), wall_s=o["wall_s"],
                        cpu_s=float("nan"), force_evals_per_step=1, hg="", dt_safety="", **measures(o)))
    for variant in variants:
        r = lammps_tl.run_hole(ctx, layout, d, variant, max_steps=QUICK_STEPS if ctx.quick else None)
        measured = os.path.join(d, f"measured_lammps_{variant}")
        ctx.run([ctx.bin("peer_tl"), "--action", "measure", "--trace", r["trace"], "--history", r["history"],
                 "--out", measured] + common, os.path.join(d, f"measure_lammps_{variant}.log"))
        m = peer_io.values(os.path.join(measured, "values_peer_tl.csv"))
        out.append(dict(base, code="lammps", variant=variant, version=r["version"], particles=r["particles"], dt=r["dt"],
                        steps=r["steps"], wall_s=r["wall_s"], cpu_s=r["cpu_s"],
                        force_evals_per_step=r["force_evals_per_step"], hg=r["hg"], dt_safety=r["dt_safety"],
                        **measures(m)))
    for r in out:
        r["particle_steps_per_s"] = r["particles"] * r["steps"] / r["wall_s"] if r["wall_s"] > 0 else float("nan")
    return out


def run_case(ctx, case, d):
    import lammps_tl
    if case[0] == "hole":
        return run_hole_case(ctx, case, d)
    scene, kind, ps, rows, variants = case
    common = ["--scene", scene, "--kind", kind, "--ps", repr(ps), "--rows", str(rows)]
    layout = os.path.join(d, "layout")
    os.makedirs(layout, exist_ok=True)
    ctx.run([ctx.bin("peer_tl"), "--action", "layout", "--out", layout] + common, os.path.join(d, "layout.log"))
    s = peer_io.settings(layout)
    pub = published(ctx.root).get(kind, float("nan"))
    base = dict(case=case_name(case), scene=scene, kind=kind, ps=ps, rows=rows, n="", published=pub)

    def measures(values):
        out = {k: values[k] for k in ("c_L", "c_plate", "c_bar")}
        for k in ("wave_speed", "plateau_over_p0", "thickness_spread_over_p0"):
            out[k] = values[k] if not ctx.quick else float("nan")
        return out

    # Ours first: our strip at the same resolution, by the function our driver runs.
    ours_dir = os.path.join(d, "ours")
    ctx.run([ctx.bin("peer_tl"), "--action", "ours", "--out", ours_dir] + common, os.path.join(d, "ours.log"))
    o = peer_io.values(os.path.join(ours_dir, "values_peer_tl.csv"))
    rows_out = [dict(base, code="ours", variant="ours",
                     version=peer_io.header(os.path.join(ours_dir, "values_peer_tl.csv")).get("code_version", ""),
                     particles=int(o["particles"]), dt=o["dt"], steps=int(o["steps"]), wall_s=o["wall_s"],
                     cpu_s=float("nan"), force_evals_per_step=1, hg="", dt_safety="", **measures(o))]
    for variant in variants:
        r = lammps_tl.run(ctx, layout, d, variant, max_steps=QUICK_STEPS if ctx.quick else None)
        measured = os.path.join(d, f"measured_lammps_{variant}")
        ctx.run([ctx.bin("peer_tl"), "--action", "measure", "--trace", r["trace"], "--out", measured] + common,
                os.path.join(d, f"measure_lammps_{variant}.log"))
        m = peer_io.values(os.path.join(measured, "values_peer_tl.csv"))
        rows_out.append(dict(base, code="lammps", variant=variant, version=r["version"], particles=r["particles"],
                             dt=r["dt"], steps=r["steps"], wall_s=r["wall_s"], cpu_s=r["cpu_s"],
                             force_evals_per_step=r["force_evals_per_step"], hg=r["hg"], dt_safety=r["dt_safety"],
                             **measures(m)))
    for r in rows_out:
        r["particle_steps_per_s"] = r["particles"] * r["steps"] / r["wall_s"] if r["wall_s"] > 0 else float("nan")
    if int(s["particles"]) != rows_out[0]["particles"]:
        raise RuntimeError(f"scene_tl: our run has {rows_out[0]['particles']} particles, the layout {int(s['particles'])}")
    return rows_out


def compare_hole(rows):
    """The sheet: each peer run against ours (neo-Hookean, the scene's law) and ours with Hooke (the peer's law), for
    the readouts of scenes::hole_stress; theory = the linear FEM concentration is in I-hole's rows, not here:
    Kirsch's 3 sigma (infinite sheet) is the theory column."""
    from run_peers import num, ratio
    ours = {(r["case"], r["variant"]): r for r in rows if r["code"] == "ours"}
    out = []
    for r in rows:
        if r["code"] == "ours" or r.get("scene") != "hole":
            continue
        for law in ("ours", "ours_hooke"):
            o = ours.get((r["case"], law))
            if o is None:
                continue
            speed = num(o["particle_steps_per_s"]) * num(o["force_evals_per_step"])
            peer_speed = num(r["particle_steps_per_s"]) * num(r["force_evals_per_step"])
            for q in ("peak_sigma1_MPa", "sigma1_hole_top_MPa", "smoothed_sigma1_hole_top_MPa"):
                out.append(dict(scene=NAME, case=r["case"], quantity=q, dp=r["ps"],
                                published=r["published"] if q == "peak_sigma1_MPa" else float("nan"),
                                theory=r["kirsch_MPa"], ours=o[q], code=r["code"], variant=f"{r['variant']}_vs_{law}",
                                peer=r[q], peer_over_ours=ratio(r[q], o[q]), ours_over_theory=ratio(o[q], r["kirsch_MPa"]),
                                peer_over_theory=ratio(r[q], r["kirsch_MPa"]),
                                ours_particle_steps_per_s=o["particle_steps_per_s"],
                                peer_particle_steps_per_s=r["particle_steps_per_s"],
                                ours_force_evals_per_step=o["force_evals_per_step"],
                                peer_force_evals_per_step=r["force_evals_per_step"],
                                ours_over_peer_per_force_eval=speed / peer_speed if peer_speed > 0 else float("nan"),
                                note=f"readout by scenes::hole_stress for both at rest (peer settle_change "
                                     f"{num(r['settle_change']):.2g}, ours {num(o['settle_change']):.2g}); theory = "
                                     f"Kirsch 3 sigma; ours: {'neo-Hookean' if law == 'ours' else 'Hooke'}; "
                                     f"the peer: MACHDYN's linear hypo-elastic pair"))
    return out


def compare(rows):
    from run_peers import num, ratio
    ours = {r["case"]: r for r in rows if r["code"] == "ours" and r.get("scene") != "hole"}
    out = compare_hole(rows)
    for r in rows:
        if r["code"] == "ours" or r["case"] not in ours or r.get("scene") == "hole":
            continue
        o = ours[r["case"]]
        theory = r["c_plate"] if r["kind"] == "stress" else r["c_L"]
        speed = num(o["particle_steps_per_s"]) * num(o["force_evals_per_step"])
        peer_speed = num(r["particle_steps_per_s"]) * num(r["force_evals_per_step"])
        note = (f"pulse centroids at x = L/3, 2L/3 by scenes::measure_wave for both; theory = plate speed "
                f"sqrt(E/(rho(1-nu^2))) (plane strain); the thesis's c_b = sqrt(E/rho) = {num(r['c_bar']):g}; "
                f"peer/c_b - 1 = {ratio(r['wave_speed'], r['c_bar']):.4g}, ours/c_b - 1 = {ratio(o['wave_speed'], r['c_bar']):.4g}"
                if r["kind"] == "stress" else
                "pulse centroids at x = L/3, 2L/3 by scenes::measure_wave for both; theory = c_L (sides held)")
        out.append(dict(scene=NAME, case=r["case"], quantity=f"wave_speed_{r['kind']}", dp=r["ps"], published=r["published"],
                        theory=theory, ours=o["wave_speed"], code=r["code"], variant=r["variant"], peer=r["wave_speed"],
                        peer_over_ours=ratio(r["wave_speed"], o["wave_speed"]),
                        ours_over_theory=ratio(o["wave_speed"], theory), peer_over_theory=ratio(r["wave_speed"], theory),
                        ours_particle_steps_per_s=o["particle_steps_per_s"],
                        peer_particle_steps_per_s=r["particle_steps_per_s"],
                        ours_force_evals_per_step=o["force_evals_per_step"],
                        peer_force_evals_per_step=r["force_evals_per_step"],
                        ours_over_peer_per_force_eval=speed / peer_speed if peer_speed > 0 else float("nan"),
                        note=note))
    return out
