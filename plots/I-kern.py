#!/usr/bin/env python3
"""I-kern: Ismail 2009 Figs 2.3-2.8, the cover functions and their derivatives in 1D, and Fig 2.7.

figures/I-kern.png        six panels: Lucy (2.3), cubic B-spline (2.4), Gaussian (2.5), mollifier (2.6),
                          modified mollifier vs scaled Gaussians (2.7), modified mollifier (2.8). As in the
                          thesis's Fig 2.8 the derivatives are scaled for illustration (scale in the legend);
                          the shaded band is W'' > 0, the tensile-instability range of Section 4.7.1.
figures/I-kern_share.png  share of the support with W'' > 0 by measure, against the thesis's 67% and 82%.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np  # noqa: E402
import plotstyle  # noqa: E402
from plotstyle import plt  # noqa: E402

TITLES = {"lucy": "Fig 2.3  Lucy (2.13)", "cubic_spline": "Fig 2.4  cubic B-spline (2.14)",
          "gaussian": "Fig 2.5  Gaussian (2.15), cut at r = 3", "mollifier": "Fig 2.6  mollifier (2.17)",
          "modified_mollifier": "Fig 2.8  modified mollifier (2.19)"}


def kernel_panel(ax, df, name):
    k = df[df.kernel == name]
    x = k.x.to_numpy()
    for col, label, style in (("W", "W", "-"), ("dWdx", "dW/dr", "--"), ("d2Wdx2", "d2W/dr2", ":")):
        y = k[col].to_numpy()
        s = np.max(np.abs(y))
        ax.plot(x, y / s, style, label=f"{label} / {s:.3g}")
    pos = k.d2Wdx2.to_numpy() > 0
    ax.fill_between(x, -1.05, 1.05, where=pos, color="tab:red", alpha=0.08, lw=0, label="W'' > 0")
    ax.set_title(TITLES[name])
    ax.set_xlabel("(x - x')/h")
    ax.set_ylim(-1.05, 1.05)
    ax.legend(loc="lower left", fontsize=6)


def main():
    args = plotstyle.parse_args(__doc__)
    curves = plotstyle.read(args.results, "curves.csv")
    fig27 = plotstyle.read(args.results, "fig2_7.csv")
    shares = plotstyle.read(args.results, "w2_positive_share.csv")

    fig, axes = plt.subplots(2, 3, figsize=(11, 6.5))
    order = ["lucy", "cubic_spline", "gaussian", "mollifier", None, "modified_mollifier"]
    for ax, name in zip(axes.flat, order):
        if name:
            kernel_panel(ax, curves, name)
    ax = axes.flat[4]
    ax.plot(fig27.r, fig27.modified_mollifier_unnormalised, "k-", label="modified mollifier (G = 1)")
    ax.plot(fig27.r, fig27.gauss_3r, "C1--", label="$e^{-(3r)^2-1}$ (reading used)")
    ax.plot(fig27.r, fig27.gauss_printed_r_over_3, "C2:", label="$e^{-(r/3)^2-1}$ as printed (2.18)")
    ax.set_title("Fig 2.7  modified mollifier vs scaled Gaussian")
    ax.set_xlabel("r = |x - x'|/h")
    ax.set_ylim(0, 0.42)
    ax.legend(loc="lower center", fontsize=6)
    plotstyle.save(fig, args.figures, "I-kern", curves)

    fig, ax = plt.subplots(figsize=(7, 3.4))
    cols = [("share_1d_length", "1D length"), ("share_2d_area", "2D area"), ("share_3d_volume", "3D volume"),
            ("share_1d_mass", "1D mass")]
    xs = np.arange(len(shares))
    for i, (c, lab) in enumerate(cols):
        ax.bar(xs + (i - 1.5) * 0.2, shares[c], 0.2, label=lab)
    ax.axhline(0.67, color="k", ls="--", lw=0.8, label="67%: cubic B-spline, thesis 4.7.1")
    ax.axhline(0.82, color="k", ls=":", lw=0.8, label="82%: 'mollifier', thesis 4.7.1")
    ax.set_xticks(xs)
    ax.set_xticklabels([f"{k}\nr* = {q:.4f}" for k, q in zip(shares.kernel, shares.q_inflection)], fontsize=7)
    ax.set_ylabel("share of the support with W'' > 0")
    ax.set_ylim(0, 1.25)
    ax.legend(fontsize=7, ncol=3, loc="upper left")
    plotstyle.save(fig, args.figures, "I-kern_share", shares)


if __name__ == "__main__":
    main()
