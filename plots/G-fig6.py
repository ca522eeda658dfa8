#!/usr/bin/env python3
"""G-fig6 (Figs 6 and 7): two rubber rings colliding at 0.059 each, without (eps = 0) and with (eps = 0.3) the
artificial stress: configurations coloured by sigma_xx, the kinetic and elastic energies, the rings'
centre-of-mass velocities with the contact interval, and the fragments of each ring against time."""
import matplotlib.pyplot as plt
import numpy as np

import plate_plots
import plotstyle as ps

args = ps.parse_args(__doc__)
summary = ps.read(args.results, "summary.csv")
for tag, fig_no in (("eps0", 6), ("eps0.3", 7)):
    frames = ps.read(args.results, f"frames_{tag}.csv")
    times = np.sort(frames.t.unique())
    picks = times[np.linspace(0, len(times) - 1, min(6, len(times))).round().astype(int)]
    fig = plate_plots.frames_figure(frames, picks, f"Gray 2001 Fig {fig_no}: colliding rings, eps = {tag[3:]}",
                                    ncols=2, panel_width=5.0)
    ps.save(fig, args.figures, f"G-fig6_fig{fig_no}_{tag}", frames)

fig, axes = plt.subplots(1, 3, figsize=(13, 3.6))
for tag, color in (("eps0", "C3"), ("eps0.3", "C0")):
    t = ps.read(args.results, f"trace_{tag}.csv")
    ax = axes[0]
    ax.plot(t.t, t.kinetic, color=color, label=f"kinetic, {tag}")
    ax.plot(t.t, t.kinetic_com, color=color, ls=":", label=f"kinetic of the centres of mass, {tag}")
    ax.plot(t.t, t.elastic, color=color, ls="--", label=f"elastic, {tag}")
    ax = axes[1]
    ax.plot(t.t, t.v_right, color=color, label=f"right ring, {tag}")
    ax.plot(t.t, t.v_left, color=color, ls="--", label=f"left ring, {tag}")
    touching = t[t.contact == 1]
    if len(touching):
        ax.axvspan(touching.t.min(), touching.t.max(), color=color, alpha=0.08)
    ax = axes[2]
    ax.step(t.t, np.maximum(t.fragments_left, t.fragments_right), where="post", color=color, label=f"fragments, {tag}")
    ax.plot(t.t, t.stray / 10.0, color=color, ls=":", label=f"stray particles / 10, {tag}")
axes[0].set_xlabel("t")
axes[0].set_ylabel(r"energy ($\rho_0 c_0^2$ cm$^2$)")
axes[0].legend(fontsize=6)
axes[1].set_xlabel("t")
axes[1].set_ylabel("centre-of-mass x velocity / $c_0$")
axes[1].set_title("shaded: the rings' main pieces interact", fontsize=8)
axes[1].legend(fontsize=6)
axes[2].set_xlabel("t")
axes[2].set_ylabel("most fragments of a ring (>= 10 particles)")
axes[2].legend(fontsize=6)
ps.save(fig, args.figures, "G-fig6", summary)
