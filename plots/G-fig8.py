#!/usr/bin/env python3
"""G-fig8 (Figs 8-10): the 3 x 1 slab pulled by its end bands (black) with von Mises plasticity. Fig 8: eps = 0,
the unphysical fracture; Fig 9: eps = 0.3 up to t = 394; Fig 10: eps = 0.3 necking to fracture; all coloured by
sigma_xx. Main figure: the neck width (cm) against time and strain for every run, the
resolution study included, with the fracture times (the ends parted) marked."""
import glob
import os

import matplotlib.pyplot as plt
import numpy as np

import plate_plots
import plotstyle as ps

args = ps.parse_args(__doc__)
summary = ps.read(args.results, "summary.csv")


def frame_times(frames, t_from, t_to, count):
    times = np.sort(frames.t.unique())
    times = times[(times >= t_from - 1e-9) & (times <= t_to + 1e-9)]
    if len(times) == 0:
        return []
    return times[np.linspace(0, len(times) - 1, min(count, len(times))).round().astype(int)]


f0 = ps.read(args.results, "frames_eps0.csv")
fig = plate_plots.frames_figure(f0, frame_times(f0, 0, f0.t.max(), 5), "Gray 2001 Fig 8: slab, eps = 0 (standard SPH)")
ps.save(fig, args.figures, "G-fig8_fig8_eps0", f0)
f3 = ps.read(args.results, "frames_eps0.3.csv")
vlim = np.nanpercentile(np.abs(f3.sxx), 99)
fig = plate_plots.frames_figure(f3, frame_times(f3, 0, 394, 5), "Gray 2001 Fig 9: slab, eps = 0.3, up to t = 394", vlim)
ps.save(fig, args.figures, "G-fig8_fig9_eps0.3", f3)
fig = plate_plots.frames_figure(f3, frame_times(f3, 394, f3.t.max(), 5), "Gray 2001 Fig 10: slab, eps = 0.3, necking", vlim)
ps.save(fig, args.figures, "G-fig8_fig10_eps0.3", f3)

runs = [("trace_eps0.csv", "eps = 0", summary.dp.iloc[0]), ("trace_eps0.3.csv", "eps = 0.3", summary.dp.iloc[0])]
for path in sorted(glob.glob(os.path.join(args.results, "trace_eps0.3_dp*.csv"))):
    dp = float(os.path.basename(path)[len("trace_eps0.3_dp"):-4])
    runs.append((os.path.basename(path), "eps = 0.3", dp))
fig, axes = plt.subplots(1, 3, figsize=(13, 3.6))
for i, (name, label, dp) in enumerate(runs):
    t = ps.read(args.results, name)
    t = t[t.parted == 0]
    color = f"C{i}"
    lab = f"{label}, dp = {dp:g}"
    axes[0].plot(t.t, t.neck_width, color=color, label=lab)
    axes[1].plot(t.strain, t.neck_width / t.median_width, color=color, label=lab)
    axes[2].plot(t.t, t.strain, color=color, label=lab)
    row = summary[(summary.dp == dp) & ((summary.eps > 0) == (label != "eps = 0"))]
    if len(row) and row.fracture_time.iloc[0] > 0:
        axes[0].axvline(row.fracture_time.iloc[0], color=color, ls=":", lw=0.8)
axes[0].set_xlabel("t")
axes[0].plot([542], [0.16], "k*", ms=9, label="paper: at t = 542 the neck ~10 x 0.016, and it fractures")
axes[0].set_ylabel("neck width (cm; until the ends part, dotted)")
axes[0].legend(fontsize=7)
axes[1].set_xlabel("strain of the ends' separation")
axes[1].set_ylabel("neck width / median width")
axes[2].set_xlabel("t")
axes[2].set_ylabel("strain")
tt = np.linspace(0, max(axes[2].get_xlim()[1], 1), 100)
meta = summary.attrs["meta"]
accel = float(meta.get("param.end-accel", "nan"))
if np.isfinite(accel):
    length = np.round(3.0 / summary.dp.iloc[0]) * summary.dp.iloc[0]
    axes[2].plot(tt, accel * tt**2 / length, "k:", lw=0.8, label="rigid bands: a t$^2$ / length")
axes[2].plot([394], [0.13], "k*", ms=9, label="paper: strain ~0.13 at t = 394 (Fig 10)")
axes[2].legend(fontsize=7)
ps.save(fig, args.figures, "G-fig8", summary)
