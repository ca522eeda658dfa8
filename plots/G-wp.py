#!/usr/bin/env python3
"""G-wp: work-precision of the plate period: error against wall time on 1 and 2 threads."""
import matplotlib.pyplot as plt

import plotstyle as ps

args = ps.parse_args(__doc__)
wp = ps.read(args.results, "work_precision.csv")
fig, axes = plt.subplots(1, 2, figsize=(10, 3.8))
for th, g in wp.groupby("threads"):
    axes[0].loglog(g.wall_s, g.relative_error, "o-", label=f"{th} thread(s)")
    for _, r in g.iterrows():
        axes[0].annotate(f"n={int(r.n)}", (r.wall_s, r.relative_error), fontsize=6)
    axes[1].semilogx(g.particles, g.particle_steps_per_s, "o-", label=f"{th} thread(s)")
axes[0].set_xlabel("wall time [s]")
axes[0].set_ylabel(r"$|T(n) - T_\infty| / T_\infty$")
axes[0].set_title(f"period error (T_inf = {wp.T_inf.iloc[0]:.1f})")
axes[1].set_xlabel("particles")
axes[1].set_ylabel("particle-steps / s")
for ax in axes:
    ax.legend()
ps.save(fig, args.figures, "G-wp", wp)
