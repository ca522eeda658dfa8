#!/usr/bin/env python3
"""G-disp: Gray et al. 2001 Section 5 lattice sums against h/dp (square and face-centred) and f_xx against n."""
import matplotlib.pyplot as plt

import plotstyle as ps

args = ps.parse_args(__doc__)
sweep = ps.read(args.results, "coefficients_vs_h.csv")
by_n = ps.read(args.results, "f_vs_n.csv")
n = sweep.attrs["meta"].get("param.n", "4")

fig, axes = plt.subplots(2, 3, figsize=(11, 6.2))
panels = [("B_x", r"$B_x\,\Delta p^2$"), ("B_y", r"$B_y\,\Delta p^2$"), ("A_x", r"$A_x\,\Delta p$"),
          ("f_xx", rf"$f_{{xx}}\,\Delta p^2$ (n = {n})"), ("f_yy", rf"$f_{{yy}}\,\Delta p^2$ (n = {n})")]
styles = {"square": dict(color="C0", label="square"), "face_centred": dict(color="C3", label="face-centred")}
for ax, (col, label) in zip(axes.flat, panels):
    for lat, g in sweep.groupby("lattice"):
        ax.plot(g.h_over_dp, g[col], **styles[lat])
    ax.axhline(0, color="k", lw=0.6)
    ax.set_xlabel(r"$h/\Delta p$")
    ax.set_title(label)
    for h in (1.2, 1.4, 1.5, 1.7):
        ax.axvline(h, color="0.6", lw=0.5, ls=":")
axes[0, 0].legend()
axes[0, 0].set_yscale("symlog", linthresh=0.1)
axes[1, 0].set_yscale("log")

ax = axes[1, 2]
for lat, g in by_n[by_n.h_over_dp == 1.0].groupby("lattice"):
    ax.plot(g.n, g.f_xx, "o-", ms=3, **styles[lat])
nn = by_n.n.unique()
ax.plot(nn, 4 * nn + 3.7, "k--", lw=0.8, label="4n + 3.7 (text, face-centred)")
ax.plot(nn, 30 * (3 * nn + 2) / (7 * 3.141592653589793), "k:", lw=0.8, label="30(3n+2)/(7$\\pi$) (5.21)")
ax.set_xlabel("n")
ax.set_title(r"$f_{xx}\,\Delta p^2$ at $h = \Delta p$")
ax.legend()
fig.suptitle(r"Gray et al. 2001 $\S$5: lattice sums at $k = (\pi/\Delta p, 0)$, cubic spline")
ps.save(fig, args.figures, "G-disp", sweep)

# Stability coefficients of (5.22)-(5.29) against h/dp.
fig, ax = plt.subplots(figsize=(5.5, 3.6))
for lat, g in sweep.groupby("lattice"):
    ax.plot(g.h_over_dp, g.Bx_over_fxx, **styles[lat])
    ax.plot(g.h_over_dp, g.By_over_fyy, ls="--", color=styles[lat]["color"], label=f"{lat}: $B_y/f_{{yy}}$")
ax.set_ylim(-0.5, 0.5)
ax.set_xlabel(r"$h/\Delta p$")
ax.set_ylabel(r"$-R\,\bar\rho^2/|\bar P-\bar S|$ needed")
ax.set_title(r"artificial-stress coefficient: $B_x/f_{xx}$ (solid), $B_y/f_{yy}$ (dashed)")
ax.legend()
ps.save(fig, args.figures, "G-disp_coefficients", sweep)
