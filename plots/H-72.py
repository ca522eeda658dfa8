#!/usr/bin/env python3
"""H-72: the 72 SPAM combinations of Hoover, Hoover & Merritt 2004 Sec. IX on the rotating hexagon, ranked by
L retention after a revolution and then by shape error."""
import numpy as np
import matplotlib.pyplot as plt
from plotstyle import parse_args, read, save

args = parse_args(__doc__)
r = read(args.results, "ranking.csv")
fig, axes = plt.subplots(1, 2, figsize=(12, 7), gridspec_kw={"width_ratios": [1, 1.3]})
colours = {"v": "C3", "shepard": "C0", "monaghan_arith": "C2"}
markers = {"gauss": "x", "particle_torque": "o", "pair_torque": "s"}
for _, row in r.iterrows():
    parts = row.variant.split("/")
    adv, tq = parts[1], next(p for p in parts if p in markers)
    lr = row.L_over_L0_360deg
    y = abs(1 - lr) if np.isfinite(lr) else 1.0
    x = row.shape_rms_360deg if np.isfinite(row.shape_rms_360deg) else 10.0
    axes[0].loglog(max(x, 1e-3), max(y, 1e-16), markers[tq], color=colours[adv], mfc="none" if "sum" in parts[0] else colours[adv])
for a, c in colours.items():
    axes[0].plot([], [], "o", color=c, label=f"dr/dt = {a}")
for t, m in markers.items():
    axes[0].plot([], [], m, color="k", label=t)
axes[0].set_xlabel("shape rms after a revolution (failed runs at 10)")
axes[0].set_ylabel("|1 - L/L0| after a revolution (failed runs at 1)")
axes[0].set_title("72 combinations (open: summed density)")
axes[0].legend(fontsize=7)
axes[1].axis("off")
top = r.head(25)
cells = [[int(x.rank), x.variant, f"{abs(1 - x.L_over_L0_360deg):.1e}", f"{x.shape_rms_360deg:.3g}"] for x in top.itertuples()]
tab = axes[1].table(cellText=cells, colLabels=["rank", "variant", "|1 - L/L0|", "shape rms"], loc="upper center",
                    colWidths=[0.08, 0.62, 0.15, 0.15], cellLoc="left")
tab.auto_set_font_size(False); tab.set_fontsize(6); tab.scale(1, 1.1)
axes[1].set_title("best 25 (full table: ranking.csv)")
save(fig, args.figures, "H-72", r)
