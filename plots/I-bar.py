#!/usr/bin/env python3
"""Ismail 2009 Figs 4.7-4.14: gauge histories of T11 in the 1D bar against T11 = -p(t - x/c) (eq 4.37),
the dt sweep to the stability boundary and the work-precision sweep."""
import matplotlib.pyplot as plt

from plotstyle import parse_args, read, save

args = parse_args(__doc__)
g = read(args.results, "gauges.csv")
cases = [("smooth_large", "Fig 4.7 large smoothing"), ("smooth_intermediate", "Figs 4.8/4.13 intermediate"),
         ("smooth_none", "Fig 4.9 no smoothing"), ("dt_0.35", "Fig 4.10 dt = 0.35 h/c_b"),
         ("dt_0.70", "Fig 4.11 dt = 0.70 h/c_b"), ("dt_1.00", "Fig 4.12 dt = h/c_b (thesis: 'at')"),
         ("material_1", "Fig 4.14 material 1"), ("material_2", "Fig 4.14 material 2"),
         ("material_3", "Fig 4.14 material 3")]
fig, axes = plt.subplots(4, 3, figsize=(12, 12))
for ax, (case, title) in zip(axes.flat, cases):
    d = g[g["case"] == case]
    for gauge, dd in d.groupby("gauge"):
        line, = ax.plot(dd["t"] * 1e6, dd["T11"] / 1e3, lw=0.8, label=f"point {gauge} (x = {dd['x'].iloc[0]:.2f} m)")
        if not case.startswith("dt_1"):
            ax.plot(dd["t"] * 1e6, dd["T11_exact"] / 1e3, "--", color=line.get_color(), lw=0.6)
    ax.set_title(title)
    ax.set_xlabel("t (us)")
    ax.set_ylabel("T11 (kPa)")
    if case.startswith("dt_1"):
        ax.set_yscale("symlog", linthresh=300)
        ax.set_title(title + ": blows up")
axes.flat[0].legend(title="SPH (solid), exact (dashed)", loc="lower left", fontsize=6)
s = read(args.results, "stability.csv")
ax = axes.flat[9]
for reading, dd in s.groupby("reading"):
    dd = dd.sort_values("dt_over_h_over_c")
    ax.semilogy(dd["dt_over_h_over_c"], dd["max_abs_T_over_p0"].clip(upper=1e6), "o", ms=3, label=reading)
ax.axvline(1.0, color="k", ls=":", label="h/c (thesis, 165 ns)")
ax.set_xlabel("dt / (h/c)")
ax.set_ylabel("max |T11| / p0")
ax.set_title("dt sweep to blow-up")
ax.legend()
w = read(args.results, "work_precision.csv")
ax = axes.flat[10]
ax.loglog(w["wall_s"], w["rms_error_over_p0"], "o-")
for _, r in w.iterrows():
    ax.annotate(f"ps={r['ps']*1e3:g} mm", (r["wall_s"], r["rms_error_over_p0"]), fontsize=6)
ax.set_xlabel("wall time of the time loop (s)")
ax.set_ylabel("RMS error of T11 / p0")
ax.set_title("work-precision (intermediate pulse)")
axes.flat[11].axis("off")
save(fig, args.figures, "I-bar", g)
