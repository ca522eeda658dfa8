#!/usr/bin/env python3
"""G-fig1: Gray et al. 2001 Fig 1, the periodic square array under pressure: final positions for h = dp and
1.5 dp, and the order parameters against the step."""
import matplotlib.pyplot as plt

import plotstyle as ps

args = ps.parse_args(__doc__)
order = ps.read(args.results, "order.csv")
final = ps.read(args.results, "final_positions.csv")
hs = sorted(final.h_over_dp.unique())
fig, axes = plt.subplots(1, len(hs) + 2, figsize=(4 * (len(hs) + 2), 3.8))
first = order[order.step == 0]
ax = axes[0]
init = final[final.h_over_dp == hs[0]]
ax.set_title("initial square array (unit cell)")
n = int(round(len(init) ** 0.5))
ax.plot([(i + 0.5) / n for i in range(n) for _ in range(n)], [(j + 0.5) / n for _ in range(n) for j in range(n)], ".", ms=3)
ax.set_aspect("equal")
for ax, h in zip(axes[1:], hs):
    f = final[final.h_over_dp == h]
    ax.plot(f.x % 1.0, f.y % 1.0, ".", ms=3)
    ax.set_aspect("equal")
    last = order[order.h_over_dp == h].iloc[-1]
    ax.set_title(f"h = {h:g} dp after {int(last.step)} steps\nshift {last['shift']:.2f}, disorder {last.disorder:.3g}")
ax = axes[-1]
for h, g in order.groupby("h_over_dp"):
    ax.semilogy(g.step, g["shift"].clip(lower=1e-6), label=f"shift order, h = {h:g} dp")
    ax.semilogy(g.step, g.disorder.clip(lower=1e-9), ls="--", label=f"disorder, h = {h:g} dp")
ax.set_xlabel("step")
ax.legend()
ps.save(fig, args.figures, "G-fig1", order)
