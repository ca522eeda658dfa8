#!/usr/bin/env python3
"""G-fig5: Gray et al. 2001 Fig 5, the large-amplitude plate (mu = 0.22, V_f = 0.05, eps = 0.3)."""
import matplotlib.pyplot as plt
import numpy as np

import plate_plots
import plotstyle as ps

args = ps.parse_args(__doc__)
tip = ps.read(args.results, "tip.csv")
frames = ps.read(args.results, "frames.csv")
fig = plate_plots.frames_figure(frames, np.linspace(0, frames.t.max(), 5), "Gray 2001 Fig 5: mu = 0.22, eps = 0.3, V_f = 0.05")
ps.save(fig, args.figures, "G-fig5_frames", frames)
fig, ax = plt.subplots(figsize=(7, 3.2))
ax.plot(tip.t, tip.y_tip, label="tip displacement")
ax2 = ax.twinx()
ax2.plot(tip.t, tip.fragments, "k:", lw=0.8, label="pieces")
ax2.set_ylim(0, max(3, tip.fragments.max() + 1))
ax2.set_ylabel("pieces")
ax.set_xlabel("t")
ax.legend(loc="upper right")
ps.save(fig, args.figures, "G-fig5", tip)
