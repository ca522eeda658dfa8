# The targets of ../shared/reproduction-targets.md that the harness reproduces, and their drivers.
# For a target T:  TARGETS += T ;  T_DRIVERS := driver names (experiments/<driver>.cpp)
# Optional:        <driver>_ARGS := extra command-line arguments for the full run
# Each driver writes into results/T/; plots/T.py turns results/T/ into figures/T*.png.

# Gray et al. 2001 Section 5: dispersion lattice sums
TARGETS += G-disp
G-disp_DRIVERS := gray2001_sec5_dispersion

# Ismail 2009 Figs 2.3-2.8: cover functions, normalisation, share of the support with W'' > 0
TARGETS += I-kern
I-kern_DRIVERS := ismail2009_fig2_3to2_8_cover_functions

# Review excerpt eq 5.59 / Ismail eq 4.48: Swegle stability map of each cover function
TARGETS += R
R_DRIVERS := review_swegle_stability_map

# I-nh: Ismail 2009 Figs 5.1-5.2, neo-Hookean plane-strain T11(l1) curves and the material code (src/materials.*)
TARGETS += I-nh
I-nh_DRIVERS := ismail2009_fig5_1to5_2_neohookean_curves

# I-interp: Ismail 2009 Figs 2.10-2.20, SPH interpolation of (x-0.5)^4, sin x and falling edges (src/interpolation_1d.*)
TARGETS += I-interp
I-interp_DRIVERS := ismail2009_fig2_10to2_20_interpolation
