#!/usr/bin/env python3
"""Ismail 2009 Figs 5.14-5.15: maximum principal Cauchy stress in the quarter sheet with a hole while the load
comes on and at rest (21 x 21); the resolution study to 201 x 201 against the linear finite-element value of the same sheet (and
Kirsch/Heywood) and the thesis's 60 MPa;
how the runs come to rest (largest particle speed) and the bias of the zero-energy-mode control."""
import os

import matplotlib.pyplot as plt

from plotstyle import parse_args, read, save

args = parse_args(__doc__)
f = read(args.results, "fields.csv")
v = read(args.results, "values_ismail2009_fig5_13to5_15_hole.csv").set_index("quantity")["value"]
times = sorted(f["t"].unique())
fig, axes = plt.subplots(3, 3, figsize=(13, 12))
vmax = f["sigma1"].max() / 1e6
for ax, t in zip(axes.flat[:5], times[-5:]):
    d = f[f["t"] == t]
    sc = ax.scatter(d["X"] + d["ux"], d["Y"] + d["uy"], c=d["sigma1"] / 1e6, s=12, cmap="viridis", vmin=0, vmax=vmax)
    ax.set_aspect("equal")
    ax.set_title(("Fig 5.15 at rest" if t == times[-1] else "Fig 5.14") + f", t = {t * 1e3:.2f} ms (deformed)")
fig.colorbar(sc, ax=axes.flat[:5].tolist(), label="max principal Cauchy stress (MPa)", shrink=0.6)
ax = axes.flat[5]
res_path = os.path.join(args.results, "resolution.csv")
res = read(args.results, "resolution.csv") if os.path.exists(res_path) else None
if res is not None:
    for series, mk, lab in (("controlled", "o-", "with the control"), ("plain", "s--", "plain (thesis's scheme)")):
        r = res[res["series"] == series]
        if len(r):
            g = r["hourglass"].iloc[0]
            ax.plot(r["n"], r["smoothed_sigma1_hole_top_MPa"], mk, label=f"SPH {lab}, gamma = {g:g}: smoothed at (0, R)")
            ax.plot(r["n"], r["sigma1_hole_top_MPa"], mk[0] + ":", alpha=0.5, label=f"SPH {lab}: particle stress at (0, R)")
    lin = res[res["series"] == "linear"]
    if len(lin):
        k = lin["smoothed_sigma1_hole_top_MPa"].iloc[0] / lin["traction_MPa"].iloc[0]
        load = res[res["series"] != "linear"]["traction_MPa"].iloc[0]
        ax.plot(lin["n"], k * load, "kx", ms=8, label=f"linear (Hooke, 1% of the load) scaled: K = {k:.3f}")
    r = res[res["series"] == "controlled"]
    ax2 = ax.twinx()
    ax2.loglog(r["n"], r["wall_s"], "k.-", lw=0.5, ms=3)
    ax2.set_ylabel("wall time of the time loop (s), black")
fem_path = os.path.join(args.results, "values_ismail2009_fig5_13to5_15_hole_resolution.csv")
fem = None
if os.path.exists(fem_path):
    vr = read(args.results, "values_ismail2009_fig5_13to5_15_hole_resolution.csv").set_index("quantity")["value"]
    if "fem_linear_sigma1_MPa" in vr:
        fem = vr["fem_linear_sigma1_MPa"]
        ax.axhline(fem, color="k", ls="--", label=f"linear FEM, same sheet: {fem:.2f} MPa (K = {vr['fem_concentration']:.3f})")
ax.axhline(v["heywood_MPa"], color="C2", label=f"Heywood (long strip) {v['heywood_MPa']:.1f} MPa")
ax.axhline(v["kirsch_MPa"], color="C3", ls=":", label="Kirsch 3 sigma (infinite sheet)")
ax.set_ylim(0, 25)
ax.annotate("thesis: 60 MPa at 21 x 21 (off scale)", xy=(0.02, 0.96), xycoords="axes fraction", color="r", fontsize=7, va="top")
ax.set_xscale("log")
ax.set_xlabel("particles per side n")
ax.set_ylabel("max principal stress (MPa)")
ax.set_title("resolution study")
ax.legend(fontsize=6, loc="lower right")
hist_path = os.path.join(args.results, "history.csv")
if os.path.exists(hist_path):
    h = read(args.results, "history.csv")
    for ax, series, title in ((axes[2, 0], "plain", "plain scheme\n(a level speed: a drift nothing resists)"),
                              (axes[2, 1], "controlled", "with the control\n(a rising speed would be the edge instability)")):
        for n, hn in h[(h["series"] == series) & (h["max_speed"] > 0)].groupby("n"):
            ax.semilogy(hn["t"] * 1e3, hn["max_speed"], lw=0.8, label=f"n = {n}")
        hl = h[(h["series"] == "linear") & (h["max_speed"] > 0)]
        if series == "controlled" and len(hl):
            ax.semilogy(hl["t"] * 1e3, 100 * hl["max_speed"], "k--", lw=0.8, label=f"linear, 1% load (x100), n = {hl['n'].iloc[0]}")
        ax.set_xlabel("t (ms)")
        ax.set_ylabel("largest particle speed (m/s)")
        ax.set_title(f"coming to rest, {title}")
        ax.legend(fontsize=6)
if res is not None:
    ax = axes[2, 2]
    gs = res[res["series"] == "gamma"].sort_values("hourglass")
    if len(gs):
        ax.plot(gs["hourglass"], gs["smoothed_sigma1_hole_top_MPa"], "o-", label="smoothed stress at (0, R)")
        if fem is not None:
            ax.axhline(fem, color="k", ls="--", label="linear FEM, same sheet")
        ax.set_xlabel("control strength gamma")
        ax.set_ylabel("max principal stress (MPa)")
        ax.set_title(f"bias of the control at n = {gs['n'].iloc[0]}")
        axz = ax.twinx()
        axz.semilogy(gs["hourglass"].clip(lower=1e-4), gs["zigzag"], "k.:", label="disorder")
        axz.set_ylabel("particle-scale disorder (black)")
        ax.legend(fontsize=6)
save(fig, args.figures, "I-hole", f)

# Work-precision (issue 43 item 6): the checked quantity, the smoothed stress at the hole's top (0, R), against
# the wall time of its run, its error measured from the resolution study's Richardson extrapolation.
rv_path = os.path.join(args.results, "values_ismail2009_fig5_13to5_15_hole_resolution.csv")
if res is not None and os.path.exists(rv_path):
    rv = read(args.results, "values_ismail2009_fig5_13to5_15_hole_resolution.csv").set_index("quantity")["value"]
    if "sigma1_hole_top_MPa_richardson" in rv.index:
        ref = rv["sigma1_hole_top_MPa_richardson"]
        fig, ax = plt.subplots(figsize=(5.5, 4))
        for series, mk, lab in (("controlled", "o-", "with the control (the series the Richardson value and the rows use)"),):
            r = res[res["series"] == series].sort_values("n")
            if len(r):
                err = (r["smoothed_sigma1_hole_top_MPa"] - ref).abs() / ref
                ax.loglog(r["wall_s"], err, mk, label=lab)
                for w, e, n in zip(r["wall_s"], err, r["n"]):
                    ax.annotate(f"{int(n)} x {int(n)}", (w, e), fontsize=6)
        ax.set_xlabel("wall time of the run [s] (one thread)")
        ax.set_ylabel("|smoothed sigma_1 at (0, R) - Richardson| / Richardson")
        ax.set_title(f"work-precision, Richardson value {ref:.2f} MPa")
        ax.legend(fontsize=7)
        save(fig, args.figures, "I-hole_wp", res)
