#!/usr/bin/env python3
"""H-fig4: Hoover, Hoover & Merritt 2004 Fig. 4, the 217-particle hexagon after a nominal rotation of 2 pi/3:
MD (a), standard SPAM with summed densities (b) and with continuity densities (c); and L/L0 against angle."""
import matplotlib.pyplot as plt
from plotstyle import parse_args, read, save

args = parse_args(__doc__)
sn = read(args.results, "snapshots.csv")
s = read(args.results, "series.csv")
variants = [("md", "(a) MD"), ("spam_sum", "(b) SPAM, summed density"), ("spam_cont", "(c) SPAM, continuity density")]
fig, axes = plt.subplots(1, 4, figsize=(14, 3.6))
for ax, (v, title) in zip(axes, variants):
    g = sn[(sn.variant == v) & ((sn.angle_deg - 120).abs() < 1)]
    ax.scatter(g.x, g.y, s=6, c=g.rho, cmap="viridis")
    ax.set_aspect("equal"); ax.set_title(title + ", 120 deg")
    ax.set_xlim(-11, 11); ax.set_ylim(-11, 11)
for v, g in s.groupby("variant"):
    axes[3].plot(g.angle_deg, g.L_over_L0, label=v)
axes[3].axvline(60, color="0.6", lw=0.8); axes[3].axvline(120, color="0.6", lw=0.8)
axes[3].plot([60, 120], [0.99, 0.95], "kx", label="paper: -1% at 60, -5% at 120")
axes[3].set_xlabel("nominal rotation (degrees)"); axes[3].set_ylabel("L / L0")
axes[3].legend(fontsize=6)
save(fig, args.figures, "H-fig4", s)
