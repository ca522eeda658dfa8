#!/usr/bin/env python3
"""G-fig2 (Figs 2 and 3): the plate with mu = 0.6, V_f = 0.05 without (eps = 0) and with (eps = 0.3) the
artificial stress: configurations coloured by sigma_xx, and the tip trace with the number of pieces."""
import matplotlib.pyplot as plt
import numpy as np

import plate_plots
import plotstyle as ps

args = ps.parse_args(__doc__)
summary = ps.read(args.results, "summary.csv")
for tag, fig_no in (("eps0", 2), ("eps0.3", 3)):
    frames = ps.read(args.results, f"frames_{tag}.csv")
    tmax = frames.t.max()
    fig = plate_plots.frames_figure(frames, np.linspace(0, tmax, 5), f"Gray 2001 Fig {fig_no}: eps = {tag[3:]}")
    ps.save(fig, args.figures, f"G-fig2_fig{fig_no}_{tag}", frames)
fig, ax = plt.subplots(figsize=(7, 3.2))
for tag in ("eps0", "eps0.3"):
    t = ps.read(args.results, f"tip_{tag}.csv")
    line, = ax.plot(t.t, t.y_tip, label=f"tip, {tag}")
    broken = t[t.fragments > 1]
    if len(broken):
        ax.plot(broken.t, broken.y_tip, "x", color=line.get_color(), ms=3, label=f"{tag}: more than one piece")
ax.set_xlabel("t")
ax.set_ylabel("tip displacement")
ax.legend()
ps.save(fig, args.figures, "G-fig2", summary)
