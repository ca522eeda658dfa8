#!/usr/bin/env python3
"""H-fig7: Hoover, Hoover & Merritt 2004 Fig. 7, the hexagon with torque scaling after 2 pi: Ldot_ij scaling
(top) and Ldot_i scaling (bottom), <v> and <v>_M; and |L/L0 - 1| against time."""
import numpy as np
import matplotlib.pyplot as plt
from plotstyle import parse_args, read, save

args = parse_args(__doc__)
sn = read(args.results, "snapshots.csv")
s = read(args.results, "series.csv")
grid = [["cont/shepard/pair_torque", "cont/monaghan_arith/pair_torque"],
        ["cont/shepard/particle_torque", "cont/monaghan_arith/particle_torque"]]
fig, axes = plt.subplots(2, 3, figsize=(11, 7))
for i in range(2):
    for j in range(2):
        v = grid[i][j]
        g = sn[(sn.variant == v) & ((sn.angle_deg - 360).abs() < 1)]
        ax = axes[i, j]
        ax.scatter(g.x, g.y, s=5, c=g.rho, cmap="viridis")
        ax.set_aspect("equal"); ax.set_xlim(-12, 12); ax.set_ylim(-12, 12)
        ax.set_title(f"{v}, 360 deg", fontsize=8)
gs = axes[0, 2].get_gridspec()
axes[0, 2].remove(); axes[1, 2].remove()
ax = fig.add_subplot(gs[:, 2])
for v, g in s.groupby("variant"):
    ax.semilogy(g.t, np.maximum(np.abs(g.L_over_L0 - 1), 1e-17), label=v)
ax.set_xlabel("time"); ax.set_ylabel("|L/L0 - 1|")
ax.legend(fontsize=6)
save(fig, args.figures, "H-fig7", s)
