#!/usr/bin/env python3
"""H-fig5: Hoover, Hoover & Merritt 2004 Fig. 5, the hexagon with velocity averaging after 2 pi/3 and 2 pi:
<v> (left) and <v>_M (right), usual continuity equation and its chain-rule form."""
import matplotlib.pyplot as plt
from plotstyle import parse_args, read, save

args = parse_args(__doc__)
sn = read(args.results, "snapshots.csv")
cols = ["cont/shepard", "cont/shepard/chain", "cont/monaghan_arith", "cont/monaghan_arith/chain", "cont/v"]
fig, axes = plt.subplots(2, len(cols), figsize=(3 * len(cols), 6))
for j, v in enumerate(cols):
    for i, a in enumerate([120, 360]):
        ax = axes[i, j]
        g = sn[(sn.variant == v) & ((sn.angle_deg - a).abs() < 1)]
        ax.scatter(g.x, g.y, s=5, c=g.rho, cmap="viridis")
        ax.set_aspect("equal"); ax.set_xlim(-12, 12); ax.set_ylim(-12, 12)
        ax.set_title(f"{v}, {a} deg", fontsize=8)
save(fig, args.figures, "H-fig5", sn)
