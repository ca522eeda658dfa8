"""make peers' total-Lagrangian scene (Ismail 2009 Section 5.4.2, Figs 5.7-5.9; I-2d): LAMMPS MACHDYN's smd/tlsph
on our 2D strip, beside ours (PySPH 1.0b1 has no total-Lagrangian scheme).

A case is one wave (kind stress: free sides, the thesis's stress wave; kind strain: sides held transversely, the
check of the set-up, whose speed c_L is not in question) at one resolution: build/bin/peer_tl --action layout writes
our particles, settings and load pulse, LAMMPS runs them (tools/peers/lammps_tl.py, tools/peers/lammps_wave.in),
peer_tl --action measure measures its gauge records with scenes::measure_wave (our driver's function), and
peer_tl --action ours runs our strip by scenes::run_wave_2d (our driver's run) at the same resolution.
The question (reference/I-2d.csv, wave_speed_stress, an open discrepancy): the thesis expects the bar speed
c_b = sqrt(E/rho) = 5000 m/s for the free-sided strip; a plane-strain code (ours; MACHDYN's 2D, F33 = 1) has the
plate speed sqrt(E/(rho (1 - nu^2))) = 5241 m/s. The codes run different discretisations (ours: plain gradient,
modified mollifier, ghost reflection at every edge; MACHDYN: corrected gradient of its spiky kernel, free surfaces
without ghosts, hourglass control), so both are reported against both speeds, each at two resolutions of the same
strip (six rows at the thesis's ps = 0.5 mm, and eleven at 0.25 mm).
Variants of the peer: tlsph (MACHDYN's hourglass control 10 and its own step), tlsph_hg0 and tlsph_ourdt (at the
thesis's resolution: what the control and the step do to the speed).
"""
import os

import peer_io

NAME = "tl"
RUN_COLUMNS = ["case", "code", "variant", "version", "scene", "kind", "ps", "rows", "particles", "dt", "steps", "wall_s",
               "cpu_s", "particle_steps_per_s", "force_evals_per_step", "hg", "dt_safety", "wave_speed",
               "plateau_over_p0", "thickness_spread_over_p0", "c_L", "c_plate", "c_bar", "published"]
QUICK_STEPS = 30


def published(root):
    """The thesis's speeds, read from reference/I-2d.csv (wave_speed_stress, wave_speed_strain; sources there)."""
    return {r["quantity"][len("wave_speed_"):]: float(r["published"])
            for r in peer_io.read_table(os.path.join(root, "reference", "I-2d.csv"))
            if r["quantity"].startswith("wave_speed_")}


def cases(quick):
    if quick:
        return [("stress_wave", "stress", 1.5e-3, 6, ["tlsph"])]
    return [("stress_wave", "stress", 0.5e-3, 6, ["tlsph", "tlsph_hg0", "tlsph_ourdt"]),
            ("stress_wave", "stress", 0.25e-3, 11, ["tlsph"]),
            ("stress_wave", "strain", 0.5e-3, 6, ["tlsph"]),
            ("stress_wave", "strain", 0.25e-3, 11, ["tlsph"])]


def case_name(case):
    scene, kind, ps, rows, _ = case
    return f"{scene}_{kind}_ps{ps * 1e3:g}mm_rows{rows}"


def run_case(ctx, case, d):
    import lammps_tl
    scene, kind, ps, rows, variants = case
    common = ["--scene", scene, "--kind", kind, "--ps", repr(ps), "--rows", str(rows)]
    layout = os.path.join(d, "layout")
    os.makedirs(layout, exist_ok=True)
    ctx.run([ctx.bin("peer_tl"), "--action", "layout", "--out", layout] + common, os.path.join(d, "layout.log"))
    s = peer_io.settings(layout)
    pub = published(ctx.root).get(kind, float("nan"))
    base = dict(case=case_name(case), scene=scene, kind=kind, ps=ps, rows=rows, published=pub)

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


def compare(rows):
    from run_peers import num, ratio
    ours = {r["case"]: r for r in rows if r["code"] == "ours"}
    out = []
    for r in rows:
        if r["code"] == "ours" or r["case"] not in ours:
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
