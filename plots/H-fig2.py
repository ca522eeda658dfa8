#!/usr/bin/env python3
"""H-fig2: Hoover, Hoover & Merritt 2004 Fig. 2, the sheared square released: L(t) and snapshots."""
import matplotlib.pyplot as plt
from plotstyle import parse_args, read, save

args = parse_args(__doc__)
s = read(args.results, "series.csv")
sn = read(args.results, "snapshots.csv")
fig, axes = plt.subplots(1, 3, figsize=(11, 3.6))
times = sorted(sn["t"].unique())
g = sn[sn.variant == "spam"]
for t, c in zip(times, ["k", "C0", "C3"]):
    h = g[g.t == t]
    axes[0].plot(h.x, h.y, ".", ms=3, color=c, label=f"t = {t:g}")
axes[0].set_aspect("equal")
axes[0].set_title("standard SPAM: u_x = y/4 released")
axes[0].legend(fontsize=6)
for v, h in s.groupby("variant"):
    axes[1].plot(h.t, h.L_over_sqrt2KI, label=v)
    axes[2].plot(h.t, h.xy_moment, label=v)
axes[1].set_xlabel("time"); axes[1].set_ylabel("L / sqrt(2 K I)")
axes[1].set_title("angular momentum (paper: zero)")
axes[1].legend()
axes[2].set_xlabel("time"); axes[2].set_ylabel("<x y> about the centre")
axes[2].set_title("the shear oscillation")
save(fig, args.figures, "H-fig2", s)
