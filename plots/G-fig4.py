#!/usr/bin/env python3
"""G-fig4: Gray et al. 2001 Fig 4, tip y(t) for n = 10, 20, 30 across H (mu = 0.22, V_f = 0.01), and the
effect of the artificial-viscosity constant on the decay per period."""
import matplotlib.pyplot as plt

import plotstyle as ps

args = ps.parse_args(__doc__)
runs = ps.read(args.results, "runs.csv")
alpha0 = float(runs.attrs["meta"].get("param.alpha", "1"))
fig, axes = plt.subplots(1, 2, figsize=(11, 3.8))
for _, r in runs.iterrows():
    t = ps.read(args.results, f"tip_n{int(r.n)}_alpha{r.alpha:g}.csv")
    if r.alpha == alpha0:
        axes[0].plot(t.t, t.y_tip, label=f"n = {int(r.n)}: T = {r.T_sph:.0f}, decay {100 * r.decay_per_period:.1f}%/period")
    if r.n == runs.n.min():
        axes[1].plot(t.t, t.y_tip, label=f"alpha = beta = {r.alpha:g}: decay {100 * r.decay_per_period:.1f}%/period")
axes[0].set_title(f"resolution (alpha = beta = {alpha0:g})")
axes[1].set_title(f"artificial viscosity at n = {int(runs.n.min())}")
for ax in axes:
    ax.set_xlabel("t")
    ax.set_ylabel("tip y")
    ax.legend()
ps.save(fig, args.figures, "G-fig4", runs)
