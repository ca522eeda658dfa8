#!/usr/bin/env python3
"""Ismail 2009 Figs 4.21-4.22: displacement (minus the pre-stretch eps0 X) of the particles of the pre-stressed
bar through time, total vs updated Lagrangian; the middle seven particles in colour."""
import matplotlib.pyplot as plt

from plotstyle import parse_args, read, save

args = parse_args(__doc__)
p = read(args.results, "particles.csv")
fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
for ax, (variant, title) in zip(axes, [("total", "Fig 4.21 total Lagrangian"), ("updated", "Fig 4.22 updated Lagrangian")]):
    d = p[p["variant"] == variant]
    mid = (d["i"].max()) // 2
    for i, dd in d.groupby("i"):
        if abs(i - mid) > 30:
            continue
        if abs(i - mid) <= 3:
            ax.plot(dd["t"] * 1e6, dd["du"] * 1e6, lw=1.2, label=f"particle {i - mid:+d}")
        else:
            ax.plot(dd["t"] * 1e6, dd["du"] * 1e6, color="0.75", lw=0.4)
    ax.set_title(title)
    ax.set_xlabel("t (us)")
    ax.set_ylabel("u - eps0 X (um)")
    ax.legend(fontsize=6, ncol=2)
save(fig, args.figures, "I-tens", p)
