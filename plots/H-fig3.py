#!/usr/bin/env python3
"""H-fig3: Hoover, Hoover & Merritt 2004 Fig. 3, kinetic (dashed) and internal (full) energies of the plane
waves in the periodic 576-particle crystal, transverse (a) and longitudinal (b)."""
import matplotlib.pyplot as plt
from plotstyle import parse_args, read, save

args = parse_args(__doc__)
df = read(args.results, "energies.csv")
fig, axes = plt.subplots(1, 2, figsize=(10, 3.6))
for ax, (wave, tag) in zip(axes, [("transverse", "(a)"), ("longitudinal", "(b)")]):
    g = df[df.wave == wave]
    ax.plot(g.t, g.U, "-", label="internal")
    ax.plot(g.t, g.K, "--", label="kinetic")
    ax.set_xlabel("time"); ax.set_ylabel("energy")
    ax.set_title(f"{tag} {wave} wave, amplitude 0.25")
    ax.legend()
save(fig, args.figures, "H-fig3", df)
