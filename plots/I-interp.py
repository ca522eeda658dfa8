#!/usr/bin/env python3
"""I-interp: Ismail 2009 Figs 2.10-2.20, SPH interpolation of f, f', f'' in 1D for several cover sizes.

One figure per thesis figure (figures/I-interp_fig2_XX.png: f, f', f'' against x, exact in black, one
curve per cover size), and figures/I-interp.png summarising the error measures: the boundary droop of
Fig 2.10, the RMS f' error against cover size for every panel, and the edge-width sweep.
"""
import matplotlib.pyplot as plt
import numpy as np

import plotstyle

args = plotstyle.parse_args(__doc__)
panels = plotstyle.read(args.results, "panels.csv")
errors = plotstyle.read(args.results, "errors.csv")
sweep = plotstyle.read(args.results, "edge_width_sweep.csv")
first = None

LABELS = [("f", "sph_f", "f"), ("df", "sph_df", "f'"), ("d2f", "sph_d2f", "f''")]

for _, p in panels.iterrows():
    df = plotstyle.read(args.results, f"curves_{p.panel}.csv")
    exact_fine = plotstyle.read(args.results, f"exact_{p.panel}.csv")
    first = df if first is None else first
    covers = sorted(df.cover.unique())
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(covers)))
    fig, axes = plt.subplots(1, 3, figsize=(11, 3.2))
    for ax, (exact, sph, name) in zip(axes, LABELS):
        for c, col in zip(covers, colours):
            d = df[df.cover == c]
            ax.plot(d.x, d[sph], "-", color=col, lw=1.0, marker=".", ms=2.5 if len(d) < 40 else 0,
                    label=f"h = {c:g} ps")
        ax.plot(exact_fine.x, exact_fine[exact], "k--", lw=1.0, label="exact")
        ax.set_xlabel("x")
        if float(p.edge_width_ps) >= 0:  # falling edges: the edge and 15 spacings either side
            half = (float(p.edge_width_ps) / 2 + 15) * float(p.ps)
            ax.set_xlim(0.5 - half, 0.5 + half)
        ax.set_title(f"{name}")
        # The f'' of the edges has spikes of order 1/ps^2 at the corners; keep the exact curve readable.
        if p.panel >= "fig2_17" and name == "f''":
            lim = np.nanpercentile(np.abs(df[sph]), 99)
            ax.set_ylim(-1.1 * lim, 1.1 * lim)
    axes[0].legend(fontsize=7)
    ps = float(p.ps)
    ghosts = ", ghost particles" if int(p.ghosts) else ""
    fig.suptitle(f"Ismail 2009 {p.panel.replace('fig', 'Fig ').replace('_', '.')}: {p.description} "
                 f"(ps = {ps:.4g}, {int(p.n_particles)} particles{ghosts})", fontsize=9)
    plotstyle.save(fig, args.figures, f"I-interp_{p.panel}", df)

# Summary figure (errors under the normalisation the curves were drawn with).
meta = panels.attrs["meta"]
e = errors[errors.normalisation == meta.get("param.normalisation", "integral")]
fig, ax = plt.subplots(2, 2, figsize=(10, 7))
d10 = plotstyle.read(args.results, "curves_fig2_10.csv")
for c in sorted(d10.cover.unique()):
    d = d10[d10.cover == c]
    ax[0, 0].plot(d.x, d.sph_f, lw=1, label=f"h = {c:g} ps")
ax[0, 0].plot(d.x, d.f, "k--", lw=1, label="exact")
ax[0, 0].set_xlim(0, 0.15)
ax[0, 0].set_ylim(0, 0.08)
ax[0, 0].set_title("Fig 2.10: droop at the boundary without ghosts (x < 0.15)")
ax[0, 0].set_xlabel("x")
ax[0, 0].legend(fontsize=7)
smooth = ["fig2_11", "fig2_12", "fig2_13", "fig2_14", "fig2_15", "fig2_16"]
edges = ["fig2_17", "fig2_18", "fig2_19", "fig2_20"]
for a, group, title in [(ax[0, 1], smooth, "smooth functions"), (ax[1, 0], edges, "falling edges")]:
    for pid in group:
        d = e[(e.panel == pid) & (e.quantity == "df")].sort_values("cover")
        desc = panels[panels.panel == pid].description.iloc[0]
        a.semilogy(d.cover, d.rms, "o-", ms=3, label=f"{pid.replace('fig', 'Fig ').replace('_', '.')}: {desc}")
    a.set_xlabel("cover size h / ps")
    a.set_ylabel("RMS error of <f'>")
    a.set_title(f"f' error against cover size, {title}")
    a.legend(fontsize=6)
s = sweep[sweep.normalisation == meta.get("param.normalisation", "integral")]
for c in sorted(s.cover.unique()):
    d = s[s.cover == c].sort_values("width_ps")
    ax[1, 1].semilogy(d.width_ps, d.rms_df, "o-", ms=3, label=f"h = {c:g} ps")
ax[1, 1].set_xlabel("edge width / ps (0 = step)")
ax[1, 1].set_ylabel("RMS error of <f'>")
ax[1, 1].set_title("falling edge: f' error against edge width")
ax[1, 1].legend(fontsize=7)
fig.suptitle(f"Ismail 2009 Figs 2.10-2.20: SPH interpolation, {meta.get('param.kernel', '')} cover, "
             f"{meta.get('param.normalisation', '')} normalisation: error measures", fontsize=9)
plotstyle.save(fig, args.figures, "I-interp", first)
