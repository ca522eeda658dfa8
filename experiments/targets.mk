# The targets of ../shared/reproduction-targets.md that the harness reproduces, and their drivers.
# For a target T:  TARGETS += T ;  T_DRIVERS := driver names (experiments/<driver>.cpp)
# Optional:        <driver>_ARGS := extra command-line arguments for the full run
# Each driver writes into results/T/; plots/T.py turns results/T/ into figures/T*.png.

# Gray et al. 2001 Section 5: dispersion lattice sums
TARGETS += G-disp
G-disp_DRIVERS := gray2001_sec5_dispersion
