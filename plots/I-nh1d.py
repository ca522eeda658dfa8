#!/usr/bin/env python3
"""Ismail 2009 Figs 5.4-5.6: the 1D neo-Hookean wave, and T11 at the centre of the 15 mm bar stretched to 90 mm
against the static curve (eq 5.5, l2 = l3 = 1) for nu = 0.3 and 0.49, with 1x, 2x, 4x the loading time."""
import matplotlib.pyplot as plt

from plotstyle import parse_args, read, save

args = parse_args(__doc__)
w = read(args.results, "wave.csv")
c = read(args.results, "curves.csv")
v = read(args.results, "values_ismail2009_fig5_4to5_6_neohookean_1d.csv").set_index("quantity")["value"]
fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
ax = axes[0]
for gauge, dd in w.groupby("gauge"):
    line, = ax.plot(dd["t"] * 1e6, dd["T11"] / 1e3, lw=0.8, label=f"x = {dd['x'].iloc[0]:.2f} m")
    ax.plot(dd["t"] * 1e6, dd["T11_exact"] / 1e3, "--", lw=0.6, color=line.get_color())
ax.set_title("Fig 5.4 neo-Hookean wave (dashed: -p(t - x/c_L))")
ax.set_xlabel("t (us)")
ax.set_ylabel("T11 (kPa)")
ax.legend(fontsize=6)
for ax, tag, title in ((axes[1], "nu0.3", "Fig 5.5 nu = 0.3"), (axes[2], "nu0.49", "Fig 5.6 nu = 0.49")):
    for case, label in ((tag, "30 transits"), (tag + "_slow2", "60 transits"), (tag + "_slow4", "120 transits")):
        d = c[c["case"] == case]
        if len(d):
            ax.plot(d["stretch_imposed"], d["T11_centre"] / 1e9, lw=0.7, label=f"SPH centre, {label}")
    d = c[c["case"] == tag]
    ax.plot(d["stretch_imposed"], d["T11_static"] / 1e9, "k--", lw=1, label="static, eq (5.5)")
    if tag == "nu0.49":
        ax.axvline(v["peak_stretch_P11_nu0.49"], color="r", ls=":", label="peak of P11: 3.63")
    ax.set_title(title)
    ax.set_xlabel("imposed stretch l1")
    ax.set_ylabel("T11 (GPa)")
    ax.legend(fontsize=6)
save(fig, args.figures, "I-nh1d", c)
