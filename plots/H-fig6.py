#!/usr/bin/env python3
"""H-fig6: Hoover, Hoover & Merritt 2004 Fig. 6, angular momentum against time for the hexagon with
dr/dt = <v> and <v>_M, continuity densities (standard SPAM for comparison)."""
import matplotlib.pyplot as plt
from plotstyle import parse_args, read, save

args = parse_args(__doc__)
s = read(args.results, "series.csv")
fig, ax = plt.subplots(figsize=(5.5, 3.8))
for v, g in s.groupby("variant"):
    ax.plot(g.t, g.L, label=v)
L0 = s.L.iloc[0]
ax.axhline(0.5 * L0, color="0.5", ls=":", label="half of L0 (paper, after a revolution)")
ax.set_xlabel("time (one nominal revolution = 160 pi)"); ax.set_ylabel("L")
ax.legend()
save(fig, args.figures, "H-fig6", s)
