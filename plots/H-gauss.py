#!/usr/bin/env python3
"""H-gauss: Hoover, Hoover & Merritt 2004 Sec. VII, the normalised denominator D/(m R^2) = 1 - L^2/(2 K m R^2)
of Gauss's multipliers against time for the rotating hexagon, with its local minima marked."""
import numpy as np
import matplotlib.pyplot as plt
from plotstyle import parse_args, read, save

args = parse_args(__doc__)
s = read(args.results, "series.csv")
mins = read(args.results, "denominator_minima.csv")
fig, axes = plt.subplots(1, 2, figsize=(11, 3.8))
for v, g in s.groupby("variant"):
    line, = axes[0].semilogy(g.t, np.maximum(g.D_over_mR2, 1e-16), lw=0.8, label=v)
    m = mins[mins.variant == v]
    axes[0].plot(m.t, np.maximum(m.D_over_mR2, 1e-16), ".", color=line.get_color(), ms=3)
    axes[1].semilogy(g.t, np.maximum(np.abs(g.E_minus_E0 / g.E.iloc[0]), 1e-17), lw=0.8, label=v)
axes[0].set_xlabel("time"); axes[0].set_ylabel("D / (m R^2)")
axes[0].set_title("Gauss denominator: touches zero again and again")
axes[0].legend(fontsize=6)
axes[1].set_xlabel("time"); axes[1].set_ylabel("|E - E0| / E0")
axes[1].set_title("energy: held until the denominator nears zero")
save(fig, args.figures, "H-gauss", s)
