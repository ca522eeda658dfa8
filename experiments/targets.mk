# The targets of ../shared/reproduction-targets.md that the harness reproduces, and their drivers: the one
# declaration of which targets exist and in which order. Make includes it; reference/check.py,
# paper/build_report.py and tests/check_targets.py read it through experiments/targets.py.
# For a target T:  TARGETS += T ;  T_DRIVERS := driver names (experiments/<paper>/<driver>.cpp)
# Optional:        T_ARGS := extra command-line arguments for T's drivers (quick runs add --quick)
#                  T_RUNS := names of T's simulation runs to step as jobs of their own, and T_RUN_ARGS := the
#                  driver's arguments that select one of them (the name follows); T's driver then collects them
#                  from the store of runs (Makefile, run_rules); T_RUN_DRIVER := the driver that takes them, if T
#                  has several. Only for runs the store serves and that no other target reuses before T has run.
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
G-tab1_RUNS := H2_Vf0.001_mu0.22 H2_Vf0.01_mu0.22 H2_Vf0.03_mu0.22 H2_Vf0.05_mu0.22 H2_Vf0.001_mu0.3 H2_Vf0.01_mu0.3 H2_Vf0.03_mu0.3 H2_Vf0.05_mu0.3 H2_Vf0.001_mu0.6 H2_Vf0.01_mu0.6 H2_Vf0.03_mu0.6 H2_Vf0.05_mu0.6
G-tab1_RUN_ARGS := --coarse-reference false --rows
G-tab2_DRIVERS := gray2001_table1_2_plate_periods
G-tab2_ARGS := --table 2
# Table 2's nine rows (each with its same-n run: ~280 s each of 2500) as jobs of their own; the coarse reference
# (Fig 4's n = 10 plate) stays with the collecting run.
G-tab2_RUNS := H1_Vf0.01_mu0.22 H1_Vf0.03_mu0.22 H1_Vf0.05_mu0.22 H1_Vf0.01_mu0.3 H1_Vf0.03_mu0.3 H1_Vf0.05_mu0.3 H1_Vf0.01_mu0.6 H1_Vf0.03_mu0.6 H1_Vf0.05_mu0.6
G-tab2_RUN_ARGS := --coarse-reference false --rows
G-fig1_DRIVERS := gray2001_fig1_periodic_array
G-fig2_DRIVERS := gray2001_fig2_3_plate_fracture
G-fig4_DRIVERS := gray2001_fig4_plate_resolution
# Fig 4's five plate runs as jobs of their own (--list-runs true prints them): the plate store serves them to the
# collecting run with the stepping job's wall times (the work-precision axis of the figure).
G-fig4_RUNS := n10_alpha1 n20_alpha1 n30_alpha1 n10_alpha0.5 n10_alpha2
G-fig4_RUN_ARGS := --step-runs
G-fig5_DRIVERS := gray2001_fig5_plate_large_amplitude
G-stab_DRIVERS := gray2001_plate_stability
# Every point of the two time-step sweeps and the four whole runs as jobs of their own (the driver's --list-runs true):
# a job steps its point whatever the smaller factors gave; the collecting run stops each sweep at its first failure.
G-stab_RUNS := sweep_dp0.25_eps0_cfl0.25 sweep_dp0.25_eps0_cfl0.5 sweep_dp0.25_eps0_cfl0.75 sweep_dp0.25_eps0_cfl1 sweep_dp0.25_eps0_cfl1.25 sweep_dp0.25_eps0_cfl1.5 sweep_dp0.25_eps0_cfl1.75 sweep_dp0.25_eps0_cfl2 sweep_dp0.25_eps0_cfl2.5 sweep_dp0.25_eps0_cfl3 sweep_dp0.25_eps0.3_cfl0.25 sweep_dp0.25_eps0.3_cfl0.5 sweep_dp0.25_eps0.3_cfl0.75 sweep_dp0.25_eps0.3_cfl1 sweep_dp0.25_eps0.3_cfl1.25 sweep_dp0.25_eps0.3_cfl1.5 sweep_dp0.25_eps0.3_cfl1.75 sweep_dp0.25_eps0.3_cfl2 sweep_dp0.25_eps0.3_cfl2.5 sweep_dp0.25_eps0.3_cfl3 sweep_dp0.1_eps0_cfl0.5 sweep_dp0.1_eps0_cfl0.75 sweep_dp0.1_eps0_cfl1 sweep_dp0.1_eps0_cfl1.25 sweep_dp0.1_eps0_cfl1.5 sweep_dp0.1_eps0_cfl1.75 sweep_dp0.1_eps0_cfl2 sweep_dp0.1_eps0.3_cfl0.5 sweep_dp0.1_eps0.3_cfl0.75 sweep_dp0.1_eps0.3_cfl1 sweep_dp0.1_eps0.3_cfl1.25 sweep_dp0.1_eps0.3_cfl1.5 sweep_dp0.1_eps0.3_cfl1.75 sweep_dp0.1_eps0.3_cfl2 reference halved_dt perturbed long
G-stab_RUN_ARGS := --step-runs
G-wp_DRIVERS := gray2001_plate_work_precision
# The four resolutions as jobs of their own: the stepping job's wall time is the figure's work axis.
G-wp_RUNS := n8 n12 n16 n20
G-wp_RUN_ARGS := --step-runs
# Sections 7.2-7.3: colliding rings, the slab with von Mises plasticity (experiments/scenes/rings*, slab*),
# their stability stress test, and the table of tensile-instability cures (beyond the paper). Full runs on
# one core (AMD host, afd2d48): G-fig6 ~10 s, G-fig8 ~5 min in four run jobs (eps = 0.3 at the paper's dp = 0.016 ~230 s, eps = 0 ~60 s, the study at 0.032 and 0.064 ~25 and 3 s), G-stab-rs ~1.5 min, X ~20 s.
TARGETS += G-fig6 G-fig8 G-stab-rs X
G-fig6_DRIVERS := gray2001_fig6_7_rings
G-fig8_DRIVERS := gray2001_fig8_10_slab
# The slab's runs as jobs of their own (the driver's --list-runs true prints them): the eps = 0.3 run at the paper's
# dp = 0.016 (~220 s) bounds the target's wall time on a cluster, not the four runs in a row (~310 s).
G-fig8_RUNS := eps0 eps0.3 eps0.3_dp0.064 eps0.3_dp0.032
G-fig8_RUN_ARGS := --step-runs
G-stab-rs_DRIVERS := gray2001_rings_slab_stability
# Every point of the rings' and the slab's sweeps, the runs at the drivers' factor and at half of it (the slab's 8-seed
# ensembles) and the fast collision as jobs of their own (--list-runs true), as G-stab's.
G-stab-rs_RUNS := rings_eps0_cfl0.25 slab_eps0_cfl0.25 rings_eps0_cfl0.5 slab_eps0_cfl0.5 rings_eps0_cfl0.75 slab_eps0_cfl0.75 rings_eps0_cfl1 slab_eps0_cfl1 rings_eps0_cfl1.25 slab_eps0_cfl1.25 rings_eps0_cfl1.5 slab_eps0_cfl1.5 rings_eps0_cfl1.75 slab_eps0_cfl1.75 rings_eps0_cfl2 slab_eps0_cfl2 rings_eps0_cfl2.5 slab_eps0_cfl2.5 rings_eps0_cfl3 slab_eps0_cfl3 rings_eps0.3_cfl0.25 slab_eps0.3_cfl0.25 rings_eps0.3_cfl0.5 slab_eps0.3_cfl0.5 rings_eps0.3_cfl0.75 slab_eps0.3_cfl0.75 rings_eps0.3_cfl1 slab_eps0.3_cfl1 rings_eps0.3_cfl1.25 slab_eps0.3_cfl1.25 rings_eps0.3_cfl1.5 slab_eps0.3_cfl1.5 rings_eps0.3_cfl1.75 slab_eps0.3_cfl1.75 rings_eps0.3_cfl2 slab_eps0.3_cfl2 rings_eps0.3_cfl2.5 slab_eps0.3_cfl2.5 rings_eps0.3_cfl3 slab_eps0.3_cfl3 rings_cfl0.5 slab_cfl0.5_seed0 slab_cfl0.5_seed1 slab_cfl0.5_seed2 slab_cfl0.5_seed3 slab_cfl0.5_seed4 slab_cfl0.5_seed5 slab_cfl0.5_seed6 slab_cfl0.5_seed7 rings_cfl0.25 slab_cfl0.25_seed0 slab_cfl0.25_seed1 slab_cfl0.25_seed2 slab_cfl0.25_seed3 slab_cfl0.25_seed4 slab_cfl0.25_seed5 slab_cfl0.25_seed6 slab_cfl0.25_seed7 fast
G-stab-rs_RUN_ARGS := --step-runs
X_DRIVERS := gray2001_tensile_cures
BENCH_DRIVERS += bench_gray_scenes

# ---- Hoover, Hoover & Merritt 2004 (src/spam_*, src/core/rk4.hpp, src/spam/molecular_dynamics.*,
#      experiments/hoover2004/scenes/hexagon.*). Full-run times on 2 idle cores: H-fig1 ~45 s,
#      H-fig3 ~15 s, hexagon drivers ~10-60 s each, H-72 ~5-8 min (72 revolutions over 2 threads). ----
TARGETS += H-fig1 H-fig2 H-fig3 H-fig4 H-fig5 H-fig6 H-fig7 H-gauss H-72
H-fig1_DRIVERS := hoover2004_fig1_tensile_instability
H-fig2_DRIVERS := hoover2004_fig2_sheared_square
H-fig3_DRIVERS := hoover2004_fig3_plane_waves
H-fig4_DRIVERS := hoover2004_fig4_hexagon_md_spam
H-fig5_DRIVERS := hoover2004_fig5_velocity_averaging
H-fig6_DRIVERS := hoover2004_fig6_angular_momentum
H-fig7_DRIVERS := hoover2004_fig7_torque_scaling
H-gauss_DRIVERS := hoover2004_gauss_multipliers
H-72_DRIVERS := hoover2004_72_combinations
# The 72 combinations as jobs of their own (the driver's --list-runs true: each label with '_' for '/'), read back from
# the store of runs (hoover2004/scenes/hexagon_store.hpp) by the collecting run.
H-72_RUNS := sum_v_gauss sum_v_particle_torque sum_v_pair_torque sum_shepard_gauss sum_shepard_particle_torque sum_shepard_pair_torque sum_monaghan_arith_gauss sum_monaghan_arith_particle_torque sum_monaghan_arith_pair_torque cont_v_gauss cont_v_particle_torque cont_v_pair_torque cont_shepard_gauss cont_shepard_particle_torque cont_shepard_pair_torque cont_monaghan_arith_gauss cont_monaghan_arith_particle_torque cont_monaghan_arith_pair_torque sum_v_gauss_visc sum_v_particle_torque_visc sum_v_pair_torque_visc sum_shepard_gauss_visc sum_shepard_particle_torque_visc sum_shepard_pair_torque_visc sum_monaghan_arith_gauss_visc sum_monaghan_arith_particle_torque_visc sum_monaghan_arith_pair_torque_visc cont_v_gauss_visc cont_v_particle_torque_visc cont_v_pair_torque_visc cont_shepard_gauss_visc cont_shepard_particle_torque_visc cont_shepard_pair_torque_visc cont_monaghan_arith_gauss_visc cont_monaghan_arith_particle_torque_visc cont_monaghan_arith_pair_torque_visc sum_v_gauss_approach sum_v_particle_torque_approach sum_v_pair_torque_approach sum_shepard_gauss_approach sum_shepard_particle_torque_approach sum_shepard_pair_torque_approach sum_monaghan_arith_gauss_approach sum_monaghan_arith_particle_torque_approach sum_monaghan_arith_pair_torque_approach cont_v_gauss_approach cont_v_particle_torque_approach cont_v_pair_torque_approach cont_shepard_gauss_approach cont_shepard_particle_torque_approach cont_shepard_pair_torque_approach cont_monaghan_arith_gauss_approach cont_monaghan_arith_particle_torque_approach cont_monaghan_arith_pair_torque_approach sum_v_gauss_visc_approach sum_v_particle_torque_visc_approach sum_v_pair_torque_visc_approach sum_shepard_gauss_visc_approach sum_shepard_particle_torque_visc_approach sum_shepard_pair_torque_visc_approach sum_monaghan_arith_gauss_visc_approach sum_monaghan_arith_particle_torque_visc_approach sum_monaghan_arith_pair_torque_visc_approach cont_v_gauss_visc_approach cont_v_particle_torque_visc_approach cont_v_pair_torque_visc_approach cont_shepard_gauss_visc_approach cont_shepard_particle_torque_visc_approach cont_shepard_pair_torque_visc_approach cont_monaghan_arith_gauss_visc_approach cont_monaghan_arith_particle_torque_visc_approach cont_monaghan_arith_pair_torque_visc_approach
H-72_RUN_ARGS := --step-runs
BENCH_DRIVERS += bench_hexagon

# ---- Ismail 2009 total Lagrangian SPH (src/total_lagrangian/sph_matrices.*, src/total_lagrangian/boundary_correction.*,
#      src/total_lagrangian_{1d,2d}.*, src/core/materials.*) ----
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
# The resolution study's runs as jobs of their own (the driver's --list-runs true prints them; ctest
# run_names_declared compares): the finest (201: 200 s and 100 s) bound the target's wall time on a cluster.
I-hole_RUN_DRIVER := ismail2009_fig5_13to5_15_hole_resolution
I-hole_RUN_ARGS := --step-runs
I-hole_RUNS := controlled_n21 controlled_n41 controlled_n81 controlled_n161 controlled_n201 plain_n21 plain_n41 plain_n81 plain_n161 plain_n201 gamma_g0 gamma_g0.002 gamma_g0.005 gamma_g0.01 gamma_g0.02 gamma_g0.05 linear_n161 edge_resolution_n41 edge_resolution_n81 edge_resolution_n161 edge_resolution_n201 edge_dt0.1_n81 edge_passes3_n81 edge_nu0.3_n81 edge_variational_n81 edge_passes30_n21
BENCH_DRIVERS += bench_tl_bar bench_tl_hole
