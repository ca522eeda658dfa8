#!/usr/bin/env python3
"""R: Swegle stability map (review eq 5.59, Ismail eq 4.48) of each cover function.

figures/R.png  one row per cover function: W''(r/h) scaled to its largest magnitude, the background red
               where W'' > 0 (a neighbour at that distance is unstable under TENSION, sigma > 0) and blue
               where W'' < 0 (unstable under COMPRESSION); markers at the lattice-neighbour distances
               n dp / h for the h/dp of Gray et al. 2001 (cubic) and Ismail 2009 (the others), and the
               alternating-mode verdict of the 1D chain in the legend.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np  # noqa: E402
import plotstyle  # noqa: E402
from plotstyle import plt  # noqa: E402

ORDER = ["lucy", "cubic_spline", "gaussian", "mollifier", "modified_mollifier"]
MARKERS = ["o", "s", "^", "D", "v", "P"]


def main():
    args = plotstyle.parse_args(__doc__)
    m = plotstyle.read(args.results, "map.csv")
    nb = plotstyle.read(args.results, "neighbours.csv")
    ch = plotstyle.read(args.results, "chain_alternating_mode.csv")

    fig, axes = plt.subplots(len(ORDER), 1, figsize=(7.5, 9.5))
    for ax, name in zip(axes, ORDER):
        k = m[m.kernel == name]
        q, w2 = k.q.to_numpy(), k.d2Wdr2.to_numpy()
        s = np.max(np.abs(w2))
        ax.fill_between(q, -1.1, 1.1, where=w2 > 0, color="tab:red", alpha=0.15, lw=0)
        ax.fill_between(q, -1.1, 1.1, where=w2 < 0, color="tab:blue", alpha=0.15, lw=0)
        ax.plot(q, w2 / s, "k-", lw=1, label=f"W'' h^3 / {s:.3g}")
        for i, (hdp, g) in enumerate(nb[nb.kernel == name].groupby("h_over_dp")):
            c = ch[(ch.kernel == name) & (ch.h_over_dp == hdp)].iloc[0]
            ax.plot(g.q, g.d2Wdr2_h3 / s, MARKERS[i], ms=5, mfc="none",
                    label=f"neighbours n dp, h/dp = {hdp:g} ({g.source.iloc[0]}); chain pi-mode: {c.unstable_under}")
        ax.axhline(0, color="0.4", lw=0.5)
        ax.set_xlim(0, q.max() + q[0])
        ax.set_ylim(-1.1, 1.1)
        ax.set_title(f"{name}: red = tension-unstable (W'' > 0), blue = compression-unstable (W'' < 0)", fontsize=8)
        ax.legend(fontsize=6, loc="lower right")
    axes[-1].set_xlabel("r/h")
    plotstyle.save(fig, args.figures, "R", m)


if __name__ == "__main__":
    main()
