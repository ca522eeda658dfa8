#!/usr/bin/env python3
"""Ismail 2009 Figs 5.14-5.15: maximum principal Cauchy stress in the quarter sheet with a hole while the load
comes on and at rest (21 x 21); the resolution study to 201 x 201 against Kirsch/Heywood and the thesis's 60 MPa."""
import os

import matplotlib.pyplot as plt

from plotstyle import parse_args, read, save

args = parse_args(__doc__)
f = read(args.results, "fields.csv")
v = read(args.results, "values_ismail2009_fig5_13to5_15_hole.csv").set_index("quantity")["value"]
times = sorted(f["t"].unique())
fig, axes = plt.subplots(2, 3, figsize=(13, 8))
vmax = f["sigma1"].max() / 1e6
for ax, t in zip(axes.flat[:5], times[-5:]):
    d = f[f["t"] == t]
    sc = ax.scatter(d["X"] + d["ux"], d["Y"] + d["uy"], c=d["sigma1"] / 1e6, s=12, cmap="viridis", vmin=0, vmax=vmax)
    ax.set_aspect("equal")
    ax.set_title(("Fig 5.15 at rest" if t == times[-1] else "Fig 5.14") + f", t = {t * 1e3:.2f} ms (deformed)")
fig.colorbar(sc, ax=axes.flat[:5].tolist(), label="max principal Cauchy stress (MPa)", shrink=0.6)
ax = axes.flat[5]
res_path = os.path.join(args.results, "resolution.csv")
if os.path.exists(res_path):
    r = read(args.results, "resolution.csv")
    ax.plot(r["n"], r["smoothed_sigma1_hole_top_MPa"], "o-", label="SPH, smoothed stress at (0, R)")
    ax.plot(r["n"], r["sigma1_hole_top_MPa"], "^:", label="SPH, particle stress at (0, R)")
    ax.plot(r["n"], r["peak_sigma1_MPa"], "s--", label="SPH, particle max over the sheet")
    ax2 = ax.twinx()
    ax2.loglog(r["n"], r["wall_s"], "k.-", lw=0.5, ms=3)
    ax2.set_ylabel("wall time of the time loop (s), black")
ax.axhline(v["heywood_MPa"], color="C2", label=f"Kirsch-Heywood {v['heywood_MPa']:.1f} MPa")
ax.axhline(v["kirsch_MPa"], color="C3", ls=":", label="Kirsch 3 sigma (infinite sheet)")
ax.axhline(60, color="r", ls="--", label="thesis: 60 MPa at 21 x 21")
ax.set_xscale("log")
ax.set_xlabel("particles per side n")
ax.set_ylabel("max principal stress (MPa)")
ax.set_title("resolution study")
ax.legend(fontsize=6, loc="center right")
save(fig, args.figures, "I-hole", f)
