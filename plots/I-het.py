#!/usr/bin/env python3
"""Ismail 2009 Figs 4.16-4.19: T11 histories at the four gauges of the bar with a density change at mid-span,
with the reflected and transmitted plateaus C_r, C_t (eqs 4.45-4.46) marked."""
import matplotlib.pyplot as plt

from plotstyle import parse_args, read, save

args = parse_args(__doc__)
g = read(args.results, "gauges.csv")
v = read(args.results, "values_ismail2009_fig4_15to4_19_heterogeneous.csv").set_index("quantity")["value"]
cases = [("decrease", "Fig 4.16 decrease (rho_B = rho_A/2)"), ("increase", "Fig 4.17 increase (2 rho_A)"),
         ("very_large_increase", "Fig 4.18 very large increase (1e4 rho_A)"),
         ("very_large_decrease", "Fig 4.19 very large decrease (rho_A/100)"),
         ("very_large_decrease_dt_of_A", "Fig 4.19 with the step of A: blows up")]
fig, axes = plt.subplots(3, 2, figsize=(11, 10))
for ax, (case, title) in zip(axes.flat, cases):
    d = g[g["case"] == case]
    for gauge, dd in d.groupby("gauge"):
        ax.plot(dd["t"] * 1e6, dd["T11"] / 1e3, lw=0.8, label=f"x = {dd['x'].iloc[0]:.3f} m")
    if case.endswith("dt_of_A"):
        ax.set_yscale("symlog", linthresh=300)
    else:
        for q, ls in (("C_r_theory_", "--"), ("C_t_theory_", ":")):
            if q + case in v:
                ax.axhline(-100 * v[q + case], color="k", ls=ls, lw=0.7,
                           label=("C_r" if "r" in q[2] else "C_t") + f" (-p0) = {-100 * v[q + case]:.1f} kPa")
    ax.set_title(title)
    ax.set_xlabel("t (us)")
    ax.set_ylabel("T11 (kPa)")
    ax.legend(fontsize=6)
axes.flat[5].axis("off")
save(fig, args.figures, "I-het", g)
