#!/usr/bin/env python3
"""Ismail 2009 Figs 5.7-5.12: strain and stress waves in the 6-particle-thick plane-strain bar; T11 of the
centre particle of the 31 x 6 block against eq (5.5) for l2 = 1, 2 and the linear path."""
import matplotlib.pyplot as plt

from plotstyle import parse_args, read, save

args = parse_args(__doc__)
w = read(args.results, "waves.csv")
b = read(args.results, "block.csv")
fig, axes = plt.subplots(1, 4, figsize=(17, 4.2))
for ax, kind, title in ((axes[0], "strain", "Fig 5.7 strain wave (sides held)"), (axes[1], "stress", "Fig 5.9 stress wave (free sides)")):
    d = w[w["case"] == kind]
    for (gx, row), dd in d.groupby(["gauge_x", "row"]):
        ax.plot(dd["t"] * 1e6, dd["T11"] / 1e3, lw=0.6, color="C0" if gx < 0.07 else "C1",
                label=f"x = {gx:.2f} m" if row == 0 else None)
    ax.set_title(title + ": all 6 rows")
    ax.set_xlabel("t (us)")
    ax.set_ylabel("T11 (kPa)")
    ax.legend(fontsize=6)
for path, label, color in (("l2_1", "Fig 5.10 l2 = 1", "C0"), ("l2_2", "Fig 5.11 l2 = 2", "C1"), ("l2_linear", "Fig 5.12 l2 linear 1 -> 2", "C2")):
    d = b[b["case"] == path]
    axes[2].plot(d["l1_imposed"], d["T11"] / 1e9, color=color, lw=0.8, label=label + " (SPH centre)")
    axes[2].plot(d["l1_imposed"], d["T11_analytic"] / 1e9, "--", color=color, lw=0.8)
    axes[3].plot(d["l1_imposed"], d["F22"], color=color, lw=0.8, label=label)
    axes[3].plot(d["l1_imposed"], d["l2_imposed"], "--", color=color, lw=0.6)
axes[2].set_xlabel("imposed l1")
axes[2].set_ylabel("Cauchy T11 (GPa)")
axes[2].set_title("31 x 6 block: centre T11 (dashed: eq 5.5)")
axes[2].legend(fontsize=6)
axes[3].set_xlabel("imposed l1")
axes[3].set_ylabel("centre F22 (dashed: imposed l2)")
axes[3].set_title("transverse stretch of the centre particle")
axes[3].legend(fontsize=6)
save(fig, args.figures, "I-2d", b)
