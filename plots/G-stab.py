#!/usr/bin/env python3
"""G-stab: stability of the plate: outcome of the time-step sweep, and the long and perturbed runs."""
import matplotlib.pyplot as plt

import plotstyle as ps

args = ps.parse_args(__doc__)
sweep = ps.read(args.results, "cfl_sweep.csv")
fig, axes = plt.subplots(1, 2, figsize=(11, 3.6))
ax = axes[0]
# One row of marks per (dp, eps): the sweep at the driver's dp and the one at the papers' dp = 0.1.
rows = list(sweep.groupby(["dp", "eps"]))
for i, ((dp, eps), g) in enumerate(rows):
    ok = g[(g.blew_up == 0) & (g.fractured == 0)]
    bad = g[(g.blew_up == 1) | (g.fractured == 1)]
    ax.plot(ok.cfl, [i] * len(ok), "o", color="C2")
    ax.plot(bad.cfl, [i] * len(bad), "x", color="C3", ms=9)
ax.set_yticks(range(len(rows)), [f"dp {dp:g}, eps {eps:g}" for (dp, eps), _ in rows])
ax.set_ylim(-0.5, len(rows) - 0.5)
ax.set_xlabel("time-step factor (dt = factor h / (c_L + |v|))")
ax.set_title("time-step sweeps: o stable, x blew up or broke")
ax = axes[1]
for name in ("long", "perturbed", "reference"):
    t = ps.read(args.results, f"tip_{name}.csv")
    ax.plot(t.t, t.y_tip, lw=0.7, label=name)
ax.set_xlabel("t")
ax.set_ylabel("tip displacement")
ax.legend()
ps.save(fig, args.figures, "G-stab", sweep)
