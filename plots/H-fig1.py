#!/usr/bin/env python3
"""H-fig1: Hoover, Hoover & Merritt 2004 Fig. 1, kinetic energy of the kicked lattice under tension."""
import numpy as np
import matplotlib.pyplot as plt
from plotstyle import parse_args, read, save

args = parse_args(__doc__)
df = read(args.results, "kinetic_energy.csv")
fig, ax = plt.subplots(figsize=(5.5, 3.8))
for (variant, stress), g in df.groupby(["variant", "stress"]):
    label = f"{'standard SPAM' if variant == 'standard' else 'SPAM, dr/dt = <v>_M'}, tension {stress:g}"
    ax.semilogy(g["t"], g["K"], "-" if variant == "standard" else "--", label=label)
ax.set_xlabel("time")
ax.set_ylabel("kinetic energy K")
ax.set_title("Tensile instability: one particle kicked at 1e-10 (cf. Fig. 1)")
ax.legend()
save(fig, args.figures, "H-fig1", df)
