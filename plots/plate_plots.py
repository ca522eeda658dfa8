"""Shared drawing for the Gray et al. 2001 plate figures (tables, tip traces, configuration frames)."""
import os

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

import plotstyle as ps


def published(target):
    """The reference rows of a target (published numbers), for overlaying on a plot."""
    path = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "reference", f"{target}.csv")
    return pd.read_csv(path, comment="#", dtype=str, keep_default_na=False)


def plot_table(results, figures, target, table):
    df = ps.read(results, "periods.csv")
    ref = published(target)
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8))
    ax = axes[0]
    # The table's own runs at the coarsest dp; Table 2's same-n reading (dp H / 2, issue 14) dashed.
    main_dp = df.dp.max()
    for i, (mu, g) in enumerate(df[df.dp == main_dp].groupby("mu")):
        c = f"C{i}"
        ax.plot(g.Vf, g.T_sph, "o-", color=c, label=f"SPH, $\\mu$ = {mu:g}")
        ax.axhline(g.T_theory_thin.iloc[0], color=c, ls=":", lw=0.8)
        ax.axhline(g.T_theory_reading.iloc[0], color=c, ls="--", lw=0.8)
        pub = ref[ref.quantity.str.match(r"T_sph_H\d") & ref.quantity.str.endswith(f"_mu{mu:g}")]
        if len(pub):
            vf = [float(q.split("_Vf")[1].split("_mu")[0]) for q in pub.quantity]
            ax.plot(vf, pub.published.astype(float), "x", color=c, ms=7, label=f"published, $\\mu$ = {mu:g}")
        same_n = df[(df.dp < main_dp) & (df.mu == mu)]
        if len(same_n):
            ax.plot(same_n.Vf, same_n.T_sph, "s--", color=c, mfc="none", label=f"SPH at dp = {same_n.dp.iloc[0]:g}")
    ax.set_xlabel("$V_f$")
    ax.set_ylabel("period T")
    ax.set_title(f"Table {table}: SPH (o), published (x); theory: H (dotted), H-0.1 (dashed)")
    ax.legend(ncol=2)
    ax = axes[1]
    for name in sorted(os.listdir(results)):
        if name.startswith("tip_") and name.endswith(".csv"):
            t = ps.read(results, name)
            ax.plot(t.t, t.y_tip, lw=0.8, label=name[4:-4])
    ax.set_xlabel("t")
    ax.set_ylabel("tip displacement")
    ax.legend(fontsize=6, ncol=2)
    ps.save(fig, figures, target, df)


def frames_figure(frames, times, title, vlim=None, ncols=1, panel_width=9.0):
    """Particle configurations at the frame times closest to `times`, coloured by sigma_xx (the grey scale
    of Gray et al. Fig 2: lighter in tension), `ncols` panels per row; Fixed/Driven particles in black."""
    avail = np.sort(frames.t.unique())
    picks = [avail[np.argmin(np.abs(avail - t))] for t in times]
    picks = list(dict.fromkeys(picks))  # a time asked twice is drawn once
    nrows = -(-len(picks) // ncols)
    aspect = (np.ptp(frames.y) + 1e-9) / (np.ptp(frames.x) + 1e-9)
    height = max(1.0, panel_width * aspect) + 0.4 if ncols > 1 else 1.6
    fig, axes = plt.subplots(nrows, ncols, figsize=(panel_width * ncols, height * nrows + 0.6), sharex=True, sharey=ncols > 1,
                             squeeze=False)
    axes = axes.ravel()
    v = vlim if vlim is not None else np.nanpercentile(np.abs(frames.sxx), 99)
    for ax, t in zip(axes, picks):
        f = frames[frames.t == t]
        sc = ax.scatter(f.x, f.y, c=f.sxx, s=2, cmap="coolwarm", vmin=-v, vmax=v, linewidths=0)
        fx = f[f.fixed == 1]
        ax.scatter(fx.x, fx.y, c="k", s=1, linewidths=0)
        ax.set_aspect("equal")
        ax.set_title(f"t = {t:.0f}", fontsize=8)
    for ax in axes[len(picks):]:
        ax.set_visible(False)
    fig.colorbar(sc, ax=axes[:len(picks)].tolist(), label=r"$\sigma_{xx}$ (tension > 0)", shrink=0.8)
    fig.suptitle(title)
    return fig
