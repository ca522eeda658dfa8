#!/usr/bin/env python3
"""X (beyond the paper): the cures for the tensile instability of the Gray et al. 2001 scheme -- none, artificial
stress, XSPH, both -- on the plate (period error against thin-plate theory, broken or not), the colliding rings
(fragments, restitution) and the slab (time the ends part, clumping time), with the wall time of each run; and the
cures of both formulations on Hoover et al.'s rotating hexagon (angular momentum lost by 120 degrees): Gray's four
variants, molecular dynamics and the SPAM variants (X_hexagon)."""
import matplotlib.pyplot as plt
import numpy as np

import plotstyle as ps

args = ps.parse_args(__doc__)
df = ps.read(args.results, "cures.csv")
meta = df.attrs["meta"]


def cell(x, fmt):
    return "-" if not np.isfinite(x) or x < 0 else fmt.format(x)


rows = []
for _, r in df.iterrows():
    rows.append([r.variant,
                 "broken" if r.plate_broken else  # a signed error: cell() would hide a negative one
                 ("-" if not np.isfinite(r.plate_period_error) else f"{100 * r.plate_period_error:+.1f}%"),
                 # NaN: not applicable (the total-Lagrangian row: no contact, no fracture)
                 "n/a" if not np.isfinite(r.rings_fragments) else
                 f"{int(r.rings_fragments)}" + (" (intact)" if r.rings_fragments == 1 else " (broken)"),
                 cell(r.rings_restitution, "{:.2f}"),
                 cell(r.slab_clumping_time, "{:.0f}"),
                 cell(r.slab_fracture_time, "{:.0f}"),
                 " / ".join(cell(t, "{:.0f}") for t in (r.plate_wall_s, r.rings_wall_s, r.slab_wall_s))])
cols = ["variant", "plate: T / T_thin - 1", "rings: fragments", "rings: restitution", "slab: clumping t",
        "slab: ends part t", "wall s (plate / rings / slab)"]
fig, axes = plt.subplots(2, 1, figsize=(10, 4.6), gridspec_kw={"height_ratios": [1.1, 1.4]})
axes[0].axis("off")
tab = axes[0].table(cellText=rows, colLabels=cols, loc="center", cellLoc="center")
tab.auto_set_font_size(False)
tab.set_fontsize(7)
tab.scale(1, 1.3)
axes[0].set_title(f"Tensile-instability cures (plate dp = {meta.get('param.plate-dp')}, rings dp = "
                  f"{meta.get('param.rings-dp')}, slab dp = {meta.get('param.slab-dp')}; '-': never / not measurable)",
                  fontsize=8)
ax = axes[1]
x = np.arange(len(df))
w = 0.25
ax.bar(x - w, df.plate_wall_s, w, label="plate")
ax.bar(x, df.rings_wall_s, w, label="rings")
ax.bar(x + w, df.slab_wall_s, w, label="slab")
ax.set_xticks(x)
ax.set_xticklabels(df.variant)
ax.set_ylabel("wall time (s, one thread)")
ax.legend()
ps.save(fig, args.figures, "X", df)

hx = ps.read(args.results, "hexagon.csv")
fig, ax = plt.subplots(figsize=(8, 3.2))
labels = [f"{r.formulation}: {r.variant}" for _, r in hx.iterrows()]
loss = np.maximum(hx.L_loss_120deg.to_numpy(float), 1e-16)
colours = ["C0" if f == "gray" else "C2" if f == "md" else "C1" for f in hx.formulation]
ax.barh(np.arange(len(hx)), loss, color=colours)
for i, (_, r) in enumerate(hx.iterrows()):
    ax.text(loss[i] * 1.3, i, f"{r.L_loss_120deg:.2g}  ({r.wall_s:.2f} s{', broke' if r.broke else ''})", va="center",
            fontsize=6)
ax.set_yticks(np.arange(len(hx)))
ax.set_yticklabels(labels, fontsize=7)
ax.set_xscale("log")
ax.set_xlim(1e-16, 10)
ax.invert_yaxis()
ax.set_xlabel("1 - L/L0 at 120 degrees (rotating hexagon, 217 particles; wall time of the run)")
ax.set_title("Cures of both formulations on one scene: Gray (blue), SPAM (orange), molecular dynamics (green)", fontsize=8)
ps.save(fig, args.figures, "X_hexagon", hx)
