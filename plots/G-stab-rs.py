#!/usr/bin/env python3
"""G-stab-rs: stability of the rings and the slab: outcome of the time-step sweep on each scene with and without
the artificial stress (o ran through, x failed), and the ring collision at twice the paper's speed."""
import matplotlib.pyplot as plt

import plotstyle as ps

args = ps.parse_args(__doc__)
sweep = ps.read(args.results, "cfl_sweep.csv")
fast = ps.read(args.results, "fast_collision.csv")
fig, axes = plt.subplots(1, 2, figsize=(11, 3.4), gridspec_kw={"width_ratios": [1.4, 1]})
ax = axes[0]
labels = []
for k, ((scene, eps), g) in enumerate(sweep.groupby(["scene", "eps"])):
    ok = g[(g.failed == 0) & (g.broke == 0)]
    broke = g[(g.failed == 0) & (g.broke == 1)]
    bad = g[g.failed == 1]
    ax.plot(ok.cfl, [k] * len(ok), "o", color="C2")
    ax.plot(broke.cfl, [k] * len(broke), "s", color="C1", mfc="none")
    ax.plot(bad.cfl, [k] * len(bad), "x", color="C3", ms=9)
    labels.append(f"{scene}, eps = {eps:g}")
ax.set_yticks(range(len(labels)))
ax.set_yticklabels(labels)
ax.set_xlabel("time-step factor (dt = factor h / (c_L + |v|max))")
ax.set_title("time-step sweep: o ran through, x blew up (or broke where the smallest step did not),\n"
             "open square broke as at the smallest step (the slab without artificial stress)", fontsize=8)
ax = axes[1]
ax.axis("off")
r = fast.iloc[0]
text = (f"rings at {r.speed:g} each (2x the paper), dp = {r.dp:g}, eps = 0.3\n"
        f"solver stopped: {'yes' if r.blew_up else 'no'}\n"
        f"most fragments of a ring: {int(r.max_fragments)}\n"
        f"smallest share in the main piece: {r.min_main_share:.3f}\n"
        f"contact duration: {r.contact_duration:.1f}\n"
        f"restitution: {r.restitution:.2f}\n"
        f"wall time: {r.wall_s:.0f} s")
ax.text(0.0, 0.95, text, va="top", fontsize=7, family="monospace")
ps.save(fig, args.figures, "G-stab-rs", sweep)
