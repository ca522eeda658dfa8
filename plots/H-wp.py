#!/usr/bin/env python3
"""H-wp: work-precision of SPAM on the hexagon: the loss of L at 60 and 120 degrees against wall time over the time step."""
import matplotlib.pyplot as plt

import plotstyle as ps

args = ps.parse_args(__doc__)
wp = ps.read(args.results, "work_precision.csv")
ok = wp[(wp.failed == 0) & (wp.dt > wp.dt.min())]  # the finest step is the reference: no error of its own
fig, axes = plt.subplots(1, 2, figsize=(10, 3.8))
for deg, style in ((60, "o-"), (120, "s-")):
    axes[0].loglog(ok.wall_s, ok[f"error_{deg}deg"], style, label=f"{deg} degrees")
    axes[1].loglog(ok.dt, ok[f"error_{deg}deg"], style, label=f"{deg} degrees")
for _, r in ok.iterrows():
    axes[0].annotate(f"dt={r['dt']:g}", (r["wall_s"], r["error_60deg"]), fontsize=6)
axes[0].set_xlabel("wall time [s]")
axes[0].set_ylabel(r"$|\Delta L / L_0 - $ finest$|$")
axes[0].set_title(f"loss of L against the finest step dt = {wp.dt.min():g}")
axes[1].set_xlabel("time step")
axes[1].axvline(0.05, color="gray", lw=0.8, ls=":")
for ax in axes:
    ax.legend()
ps.save(fig, args.figures, "H-wp", wp)
