#!/usr/bin/env python3
"""I-nh: Ismail 2009 Figs 5.1 (nu = 0.3) and 5.2 (nu = 0.49): neo-Hookean plane-strain Cauchy stress T11
against the stretch l1 for fixed l2 (eq 5.5), with the Fig 5.12 loading path l2 = 1 -> 2 (dashed), the
zero crossings (o) and the maxima where dT11/dl1 = 0 (x; for l2 = 1 this is the 1D-strain loss of
stability near the thesis's stretch 3.6). Library route as lines, closed form (5.5) as sparse dots."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plotstyle  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402


def main():
    args = plotstyle.parse_args(__doc__)
    curves = plotstyle.read(args.results, "curves.csv")
    path = plotstyle.read(args.results, "path.csv")
    feats = plotstyle.read(args.results, "features.csv")
    values = plotstyle.read(args.results, "values_ismail2009_fig5_1to5_2_neohookean_curves.csv")
    val = dict(zip(values["quantity"], values["value"]))
    E = curves.attrs["meta"].get("param.E", "?")

    nus = sorted(curves["nu"].unique())
    fig, axes = plt.subplots(1, len(nus), figsize=(5.2 * len(nus), 4.2), squeeze=False)
    for ax, nu in zip(axes[0], nus):
        c = curves[curves.nu == nu]
        for l2, g in c.groupby("l2"):
            line, = ax.plot(g.l1, g.T11, lw=1.4, label=fr"$\lambda_2 = {l2:g}$")
            step = max(1, len(g) // 40)
            ax.plot(g.l1[::step], g.T11_closed_form[::step], ".", ms=2.5, color=line.get_color())
            f = feats[(feats.nu == nu) & (feats.l2 == l2)].iloc[0]
            if f.l1_zero == f.l1_zero and l2 != 1:
                ax.plot(f.l1_zero, 0, "o", mfc="none", color=line.get_color())
            if f.l1_peak == f.l1_peak:
                ax.plot(f.l1_peak, f.T11_peak, "x", ms=7, mew=1.5, color=line.get_color())
                if l2 == 1:
                    ax.annotate(fr"max at $\lambda_1$ = {f.l1_peak:.3f}", (f.l1_peak, f.T11_peak),
                                textcoords="offset points", xytext=(0, -14), ha="center", fontsize=7)
        p = path[path.nu == nu]
        ax.plot(p.l1, p.T11, "k--", lw=1.0, label=r"path $\lambda_2$: 1 $\to$ 2 (Fig 5.12)")
        key = f"path_excess_over_upper_bound_rel_nu{nu:g}"
        x = val.get(f"path_excess_l1_nu{nu:g}")
        if x is not None:
            ax.axvline(x, color="0.6", lw=0.6, ls=":")
            ax.text(x, 0.02, f" path above both\n bounding curves\n by {100 * val[key]:.1f}% here",
                    transform=ax.get_xaxis_transform(), fontsize=6.5, color="0.3")
        # The curves fall to -infinity as J -> 0: clip below at a third of the largest tension.
        top = c.T11.max()
        ax.set_ylim(-0.35 * top, 1.08 * top)
        ax.axhline(0, color="k", lw=0.5)
        fig_no = "5.1 (compressible)" if nu < 0.4 else "5.2 (nearly incompressible)"
        diff = val.get(f"max_rel_diff_T_closed_form_vs_library_nu{nu:g}", float("nan"))
        ax.set_title(fr"Fig {fig_no}: $\nu$ = {nu:g}, E = {E} GPa, $\lambda_3$ = 1" "\n"
                     f"lines: P(F) (3.64) -> T (3.33); dots: closed form (5.5); max rel. diff {diff:.1e}",
                     fontsize=8)
        ax.set_xlabel(r"stretch $\lambda_1$")
        ax.set_ylabel(r"Cauchy stress $T_{11}$ [GPa]")
        ax.legend(loc="lower right")
    plotstyle.save(fig, args.figures, "I-nh", curves)


if __name__ == "__main__":
    main()
