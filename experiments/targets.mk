# The targets of ../shared/reproduction-targets.md that the harness reproduces, and their drivers: the one
# declaration of which targets exist and in which order. Make includes it; reference/check.py,
# paper/build_report.py and tests/check_targets.py read it through experiments/targets.py.
# For a target T:  TARGETS += T ;  T_DRIVERS := driver names (experiments/<paper>/<driver>.cpp)
# Optional:        T_ARGS := extra command-line arguments for T's drivers (quick runs add --quick)
#                  T_RUN_DRIVER := the one of T's drivers whose simulation runs are jobs of their own (its
#                  frame/run_jobs.hpp options): the Makefile names the runs from its --list-runs, steps each with
#                  --step-runs <run> into results/.runs/T/<run>/ and then runs it with --runs-from, which reads them.
# Each driver writes into results/T/; plots/T.py turns results/T/ into figures/T*.png. A declared T also
# needs reference/T.csv (its published numbers) and a row in paper/targets.csv (the report's title, work
# and description); `make check-targets` (run first by `make test`) checks all of it.
# BENCH_DRIVERS: scene benchmarks run by `make bench`, each writing results/bench/<name>.csv.
# Only these line forms and '#' comments: the Python reader refuses anything else (Make variables,
# conditionals, continued lines).

# ---- Cover functions and the stability criterion (library: src/core/kernels.*, src/total_lagrangian/interpolation_1d.*) ----
# Ismail 2009 Figs 2.3-2.8: cover functions, normalisation, share of the support with W'' > 0
TARGETS += I-kern
I-kern_DRIVERS := ismail2009_fig2_3to2_8_cover_functions
# Review excerpt eq 5.59 / Ismail eq 4.48: Swegle stability map of each cover function
TARGETS += R
R_DRIVERS := review_swegle_stability_map
# Ismail 2009 Figs 2.10-2.20: SPH interpolation of (x-0.5)^4, sin x and falling edges
TARGETS += I-interp
I-interp_DRIVERS := ismail2009_fig2_10to2_20_interpolation

# ---- Gray, Monaghan & Swift 2001 (src/updated_lagrangian/lattice_sums.*, src/updated_lagrangian/gray_solver.*, experiments/scenes/plate*) ----
# Section 5: dispersion lattice sums
TARGETS += G-disp
G-disp_DRIVERS := gray2001_sec5_dispersion
# Section 7.1: the oscillating plate
TARGETS += G-tab1 G-tab2 G-fig1 G-fig2 G-fig4 G-fig5 G-stab G-wp
G-tab1_DRIVERS := gray2001_table1_2_plate_periods
G-tab1_ARGS := --table 1
# Table 1's twelve rows as jobs of their own; the coarse reference (Fig 4's n = 10 plate) stays with the collecting run.
G-tab1_RUN_DRIVER := gray2001_table1_2_plate_periods
G-tab2_DRIVERS := gray2001_table1_2_plate_periods
G-tab2_ARGS := --table 2
# Table 2's nine rows (each with its same-n run: ~280 s each of 2500) as jobs of their own; the coarse reference
# (Fig 4's n = 10 plate) stays with the collecting run.
G-tab2_RUN_DRIVER := gray2001_table1_2_plate_periods
G-fig1_DRIVERS := gray2001_fig1_periodic_array
G-fig2_DRIVERS := gray2001_fig2_3_plate_fracture
G-fig4_DRIVERS := gray2001_fig4_plate_resolution
# Fig 4's five plate runs as jobs of their own: the collecting run reads them with the stepping jobs' wall times (the
# work-precision axis of the figure).
G-fig4_RUN_DRIVER := gray2001_fig4_plate_resolution
G-fig5_DRIVERS := gray2001_fig5_plate_large_amplitude
G-stab_DRIVERS := gray2001_plate_stability
# Every point of the two time-step sweeps and the four whole runs as jobs of their own: a job steps its point
# whatever the smaller factors gave; the collecting run stops each sweep at its first failure.
G-stab_RUN_DRIVER := gray2001_plate_stability
G-wp_DRIVERS := gray2001_plate_work_precision
# The four resolutions as jobs of their own: the stepping job's wall time is the figure's work axis.
G-wp_RUN_DRIVER := gray2001_plate_work_precision
# Sections 7.2-7.3: colliding rings, the slab with von Mises plasticity (experiments/scenes/rings*, slab*),
# their stability stress test, and the table of tensile-instability cures (beyond the paper). Full runs on
# one core (AMD host, afd2d48): G-fig6 ~10 s, G-fig8 ~5 min in four run jobs (eps = 0.3 at the paper's
# dp = 0.016 ~230 s, eps = 0 ~60 s, the study at 0.032 and 0.064 ~25 and 3 s), G-stab-rs ~1.5 min, X ~20 s.
TARGETS += G-fig6 G-fig8 G-stab-rs X
G-fig6_DRIVERS := gray2001_fig6_7_rings
G-fig8_DRIVERS := gray2001_fig8_10_slab
# The slab's runs as jobs of their own: the eps = 0.3 run at the paper's dp = 0.016 (~220 s) bounds the target's
# wall time on a cluster, not the four runs in a row (~310 s).
G-fig8_RUN_DRIVER := gray2001_fig8_10_slab
G-stab-rs_DRIVERS := gray2001_rings_slab_stability
# Every point of the rings' and the slab's sweeps, the runs at the drivers' factor and at half of it (the slab's 8-seed
# ensembles) and the fast collision as jobs of their own, as G-stab's.
G-stab-rs_RUN_DRIVER := gray2001_rings_slab_stability
X_DRIVERS := gray2001_tensile_cures
BENCH_DRIVERS += bench_gray_scenes

# ---- Hoover, Hoover & Merritt 2004 (src/spam_*, src/core/rk4.hpp, src/spam/molecular_dynamics.*,
#      experiments/hoover2004/scenes/hexagon.*). Full-run times on 2 idle cores: H-fig1 ~45 s,
#      H-fig3 ~15 s, hexagon drivers ~10-60 s each, H-72 ~5-8 min (72 revolutions over 2 threads). ----
TARGETS += H-fig1 H-fig2 H-fig3 H-fig4 H-fig5 H-fig6 H-fig7 H-gauss H-72 H-wp
H-fig1_DRIVERS := hoover2004_fig1_tensile_instability
H-fig2_DRIVERS := hoover2004_fig2_sheared_square
H-fig3_DRIVERS := hoover2004_fig3_plane_waves
H-fig4_DRIVERS := hoover2004_fig4_hexagon_md_spam
H-fig5_DRIVERS := hoover2004_fig5_velocity_averaging
H-fig6_DRIVERS := hoover2004_fig6_angular_momentum
H-fig7_DRIVERS := hoover2004_fig7_torque_scaling
H-gauss_DRIVERS := hoover2004_gauss_multipliers
H-72_DRIVERS := hoover2004_72_combinations
# Work-precision and time-step stability of the hexagon's SPAM (beyond the paper; issue 43 item 6): ~1 min.
H-wp_DRIVERS := hoover2004_hexagon_work_precision
# The 72 combinations as jobs of their own (each named by its label with '_' for '/').
H-72_RUN_DRIVER := hoover2004_72_combinations
BENCH_DRIVERS += bench_hexagon

# ---- Ismail 2009 total Lagrangian SPH (src/total_lagrangian/sph_matrices.*, src/total_lagrangian/boundary_correction.*,
#      src/total_lagrangian/solver_{1d,2d}.*, src/core/materials.*) ----
# Figs 5.1-5.2: neo-Hookean plane-strain T11(l1) curves
TARGETS += I-nh
I-nh_DRIVERS := ismail2009_fig5_1to5_2_neohookean_curves
# Chapter 4: linear elastic bar, heterogeneous bar, tensile bar; chapter 5: neo-Hookean 1D, 2D, hole
TARGETS += I-bar I-het I-tens I-nh1d I-2d I-hole
I-bar_DRIVERS := ismail2009_fig4_6to4_14_bar
I-het_DRIVERS := ismail2009_fig4_15to4_19_heterogeneous
I-tens_DRIVERS := ismail2009_fig4_20to4_22_tensile
I-nh1d_DRIVERS := ismail2009_fig5_4to5_6_neohookean_1d
I-2d_DRIVERS := ismail2009_fig5_7to5_12_neohookean_2d
I-hole_DRIVERS := ismail2009_fig5_13to5_15_hole ismail2009_fig5_13to5_15_hole_resolution
# The resolution study's runs as jobs of their own: the finest (201: 200 s and 100 s) bound the target's wall time
# on a cluster.
I-hole_RUN_DRIVER := ismail2009_fig5_13to5_15_hole_resolution
BENCH_DRIVERS += bench_tl_bar bench_tl_hole
