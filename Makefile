# One command reproduces every figure and table, another runs the tests:
#   make figures   deps -> build -> every driver -> plots -> check against published numbers
#   make test      declaration check -> deps -> build -> GoogleTest (ctest) -> quick smoke run of every driver
#                  -> quick check -> the report on the quick results -> a few steps of the peers (make peers-quick)
# Other targets: make check, make paper, make peers, make studies, make bench, make bench-ab BASE=<rev>, make bench-peer, make sanitize, make deps, make clean, make check-targets,
# make list-targets, make list-runs, make archive, make verify-archive FILE=<tar.gz>, make test-paraview, make test-slurm;
# make figures LAUNCH=slurm RUN_JOBS=<n> on a cluster.
# Make's dependency graph reruns a driver only when its binary changed. Threads: `figures` and `quick` run
# NCORES drivers at a time, each single-threaded (OpenMP teams of two on 2 cores reach 1.3-1.8x, two
# single-threaded drivers side by side ~2x; oversubscribed teams spin and run many times slower), the longest
# first (LONGEST_FIRST).

PY      := /usr/bin/python3
BUILD   := build
BIN     := $(BUILD)/bin
JOBS    ?= 2
NCORES  := $(shell nproc 2>/dev/null || echo 2)
RESULTS ?= results
FIGURES ?= figures
# Set by `make test` (quick mode): extra flags for every driver.
DRIVER_FLAGS ?=
CHECK_FLAGS  ?=

DEB_PACKAGES := cmake make ninja-build g++ git pkg-config libeigen3-dev libxsimd-dev libgsl-dev libhdf5-dev libcli11-dev \
                libgtest-dev libbenchmark-dev python3-matplotlib python3-pandas

include experiments/targets.mk

# The order in which `figures` starts the targets, NCORES at a time: the longest first (their single-threaded
# run times at the default resolution, measured; a longest-processing-time-first schedule), then the rest in
# the order of targets.mk. Only the order changes, never what runs. (G-tab2 first since its same-n reading: ~8x its
# dp = 0.1 rows, measured on one core of the AMD host on 2026-12-02: ~3200 s of CPU against ~330 s.)
LONGEST_FIRST := G-tab2 G-fig8 G-fig2 I-hole G-fig4 G-wp G-tab1 G-fig5 H-72 G-stab G-stab-rs
ORDERED = $(filter $(TARGETS),$(LONGEST_FIRST)) $(filter-out $(LONGEST_FIRST),$(TARGETS))
DONE    = $(foreach t,$(ORDERED),$(RESULTS)/$(t)/.done)
FIGS    = $(foreach t,$(ORDERED),$(FIGURES)/$(t).png)

.PHONY: all figures figures-locked test test-locked sanitize check paper status-table bench bench-ab bench-peer peers peers-quick studies deps build build-drivers configure ctest results plots quick clean help timings \
        check-targets list-targets list-runs archive verify-archive test-paraview
.DEFAULT_GOAL := help

help:
	@sed -n '1,6p' Makefile | sed 's/^# \{0,1\}//'

# ---------------------------------------------------------------------------------------------------
# The targets are declared once, in experiments/targets.mk. `make -s list-targets` prints Make's reading of
# it: one line per target, target;drivers;extra arguments, then BENCH_DRIVERS;drivers; (tests/check_targets.py
# compares it with the Python reader experiments/targets.py). `make check-targets`: every declared target has
# its reference/T.csv, plots/T.py, paper/targets.csv row and driver sources, and nothing undeclared is there.
list-targets:
	@: $(foreach t,$(TARGETS),$(info $(t);$($(t)_DRIVERS);$(strip $($(t)_ARGS))))$(info BENCH_DRIVERS;$(BENCH_DRIVERS);)

check-targets: deps
	$(PY) tests/check_targets.py

# ---------------------------------------------------------------------------------------------------
# Set-up: Debian packages (apt) and the Python that can import matplotlib and pandas.
# A recipe line that installs those of the Debian packages $(1) that are missing (apt; sudo unless root).
apt_ensure = @missing=$$(for p in $(1); do dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q 'install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "make $@: installing" $$missing; \
	  SUDO=; [ "$$(id -u)" -eq 0 ] || SUDO=sudo; \
	  $$SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq --no-install-recommends $$missing; \
	fi
deps:
	$(call apt_ensure,$(DEB_PACKAGES))
	@$(PY) -c 'import matplotlib, pandas' || { echo "make deps: $(PY) cannot import matplotlib and pandas"; exit 1; }

# Ninja, not CMake's default Makefiles: it schedules the compiles of every target together, where the
# Makefiles build one target's objects at a time (the drivers of a fresh clone in 160 s instead of 238 s on 2
# cores, the same 310 s of CPU). A build directory configured with another generator is configured afresh.
CMAKE_GENERATOR_FLAGS := -G Ninja
ninja_only = @if [ -f $(1)/CMakeCache.txt ] && ! grep -qx 'CMAKE_GENERATOR:INTERNAL=Ninja' $(1)/CMakeCache.txt; then \
	  echo "$(1) was configured with another generator: configuring it afresh"; rm -rf $(1)/CMakeCache.txt $(1)/CMakeFiles; fi
configure: $(BUILD)/CMakeCache.txt
$(BUILD)/CMakeCache.txt: CMakeLists.txt | deps
	$(call ninja_only,$(BUILD))
	cmake -S . -B $(BUILD) $(CMAKE_GENERATOR_FLAGS) -DCMAKE_BUILD_TYPE=Release

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# The drivers of the declared targets only, for `make figures`: not the unit tests and the benchmarks (a
# third of the compile time of a fresh build).
DRIVERS = $(sort $(foreach t,$(TARGETS),$($(t)_DRIVERS)))
build-drivers: configure
	cmake --build $(BUILD) -j $(JOBS) --target $(DRIVERS)

# ---------------------------------------------------------------------------------------------------
# Where the drivers run. LAUNCH empty: here. LAUNCH=slurm: every driver run is a Slurm job through srun (one
# task, SRUN_CPUS CPUs, named sph-<target>), which blocks until the job ends, so Make stays the pipeline and
# Slurm the engine; RUN_JOBS driver runs are in flight at a time (make figures LAUNCH=slurm RUN_JOBS=32 on a
# cluster; the working directory must be on a file system the nodes share). make test-slurm tests it on a
# single-node Slurm of this machine.
LAUNCH    ?=
RUN_JOBS  ?= $(NCORES)
SRUN_CPUS ?= 1
SRUN_FLAGS ?=
launcher = $(if $(filter slurm,$(LAUNCH)),srun --ntasks=1 --cpus-per-task=$(SRUN_CPUS) --job-name=sph-$(1) --quiet $(SRUN_FLAGS) ,$(if $(LAUNCH),$(error LAUNCH=$(LAUNCH): only LAUNCH=slurm or empty)))

# The unit of work. A target that declares T_RUN_DRIVER (experiments/targets.mk) has its simulation runs stepped as
# jobs of their own. The runs are the driver's (--list-runs true, with the target's arguments and DRIVER_FLAGS):
# $(RUNS_MK) lists them (a line `T_RUNS += <run>` each), generated from the built drivers and read only where runs
# are made (the goals below: `make figures` and `make quick` make them in a sub-make after the build). A run job is
# the driver with --step-runs <run> into $(RESULTS)/.runs/T/<run>/, where it leaves the run's results as files with
# the usual headers and, last, its completion record; then the target's own run of that driver reads them back
# (--runs-from $(RESULTS)/.runs/T; experiments/frame/run_folder.hpp refuses, by name, a folder that is incomplete or
# of another code version or other parameters) and steps none. So Make runs the runs side by side (RUN_JOBS) and
# LAUNCH=slurm makes each a Slurm job. `T_RUN_DRIVER=` on the command line runs T whole.
SPLIT = $(foreach t,$(TARGETS),$(if $($(t)_RUN_DRIVER),$(t)))
empty :=
space := $(empty) $(empty)
RUNS_MK := $(RESULTS)/.runs/runs$(subst $(space),,$(strip $(DRIVER_FLAGS))).mk
ifneq ($(filter results plots list-runs $(RESULTS)/% $(FIGURES)/%,$(MAKECMDGOALS)),)
include $(RUNS_MK)
endif
list_runs = runs=$$($(BIN)/$($(1)_RUN_DRIVER) --list-runs true --out $(@D)/$(1) $($(1)_ARGS) $(DRIVER_FLAGS)) || exit 1; \
	for r in $$runs; do echo "$(1)_RUNS += $$r"; done;
$(RUNS_MK): experiments/targets.mk $(foreach t,$(SPLIT),$(BIN)/$($(t)_RUN_DRIVER))
	@mkdir -p $(@D)
	@($(foreach t,$(SPLIT),$(call list_runs,$(t))) true) > $@.tmp && mv $@.tmp $@ || { rm -f $@.tmp; exit 1; }
split = $(filter $(1),$(SPLIT))
run_dones = $(if $(call split,$(1)),$(foreach r,$($(1)_RUNS),$(RESULTS)/.runs/$(1)/$(r)/.done))
define run_rules
$(RESULTS)/.runs/$(1)/$(2)/.done: $(BIN)/$($(1)_RUN_DRIVER)
	@mkdir -p $$(@D)
	$(call launcher,$(1)-$(2))$(BIN)/$($(1)_RUN_DRIVER) --out $$(@D) $($(1)_ARGS) $(DRIVER_FLAGS) --step-runs $(2) && touch $$@
endef
$(foreach t,$(SPLIT),$(foreach r,$($(t)_RUNS),$(eval $(call run_rules,$(t),$(r)))))
# make -s list-runs [DRIVER_FLAGS=...]: one line per split target, target;runs (tests/test_slurm.sh counts the jobs with it).
list-runs:
	@: $(foreach t,$(SPLIT),$(info $(t);$(strip $($(t)_RUNS))))

# Drivers -> results/<target>/ -> plots/<target>.py -> figures/<target>.png. A split target's run driver reads its
# runs from their folders (--runs-from); its other drivers run as usual.
runs_from = $(if $(and $(call run_dones,$(1)),$(filter $(2),$($(1)_RUN_DRIVER))), --runs-from $(RESULTS)/.runs/$(1))
define target_rules
$(RESULTS)/$(1)/.done: $(foreach d,$($(1)_DRIVERS),$(BIN)/$(d)) $(call run_dones,$(1))
	@mkdir -p $$(@D)
	$(foreach d,$($(1)_DRIVERS),$(call launcher,$(1))$(BIN)/$(d) --out $$(@D) $($(1)_ARGS) $(DRIVER_FLAGS)$(call runs_from,$(1),$(d)) &&) touch $$@
$(FIGURES)/$(1).png: plots/$(1).py plots/plotstyle.py $(RESULTS)/$(1)/.done
	@mkdir -p $(FIGURES)
	$(PY) plots/$(1).py --results $(RESULTS)/$(1) --figures $(FIGURES)
endef
$(foreach t,$(TARGETS),$(eval $(call target_rules,$(t))))

results: $(DONE)
plots: $(FIGS)

$(RESULTS)/check.csv: $(DONE) reference/check.py $(wildcard reference/*.csv)
	$(PY) reference/check.py --results $(RESULTS) $(CHECK_FLAGS)

# One pipeline at a time per results folder (issue 47 item 2): make figures and make test hold a lock on their
# results folder (tools/results_lock.sh) while their sub-make runs; a second one into the same folder is refused
# at once, naming the first.
LOCK = tools/results_lock.sh

# The main job: everything at paper resolution, then the check (fails the make on any FAIL), then the
# timing table of the drivers (results/timings.csv) and the report (paper/build/index.html), both also when
# the check fails (the report shows the FAIL rows).
figures:
	@$(LOCK) $(RESULTS) "make figures" $(MAKE) --no-print-directory figures-locked
figures-locked: deps build-drivers
	@date +%s > $(RESULTS)/.figures_start 2>/dev/null || { mkdir -p $(RESULTS); date +%s > $(RESULTS)/.figures_start; }
	OMP_NUM_THREADS=1 $(MAKE) --no-print-directory -j $(RUN_JOBS) plots
	@status=0; $(MAKE) --no-print-directory check || status=$$?; \
	  $(MAKE) --no-print-directory timings; \
	  $(PY) paper/build_report.py --results $(RESULTS) --figures $(FIGURES) --reference reference \
	    --out paper/build/index.html || status=1; \
	  echo "make figures: $$(( $$(date +%s) - $$(cat $(RESULTS)/.figures_start) )) s after the build"; \
	  $(PY) tools/status_table.py --results $(RESULTS) --check || true; exit $$status

# results/timings.csv: every driver's timing_<driver>.csv (target, driver, wall seconds, particle-steps,
# threads; written by the driver frame), merged, with the totals.
timings:
	@$(PY) tools/timings.py --results $(RESULTS)

all: figures

# README.md's table of the targets and their check status, from the check of the last full run (tools/status_table.py);
# make figures says when the README's table no longer agrees with its check.
status-table:
	$(PY) tools/status_table.py --results $(RESULTS) --write

check:
	$(PY) reference/check.py --results $(RESULTS) $(CHECK_FLAGS)

# The tests: unit tests, then every driver in --quick mode with its plot, then the quick check.
ctest: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

quick:
	OMP_NUM_THREADS=1 $(MAKE) --no-print-directory -j $(RUN_JOBS) RESULTS=results/quick FIGURES=results/quick/figures DRIVER_FLAGS=--quick plots
	$(MAKE) --no-print-directory RESULTS=results/quick CHECK_FLAGS=--quick check
	$(MAKE) --no-print-directory RESULTS=results/quick timings
	$(PY) paper/build_report.py --results results/quick --figures results/quick/figures --reference reference \
	  --out results/quick/report/index.html

test:
	@$(LOCK) results/quick "make test" $(MAKE) --no-print-directory test-locked
test-locked: deps check-targets build ctest quick peers-quick

# A citable archive of one reproduction (tools/archive.py): results (with the run jobs' folders),
# figures, the report, PROVENANCE.json (code version and uncommitted changes, every driver command line, the
# Debian package versions, compiler, machine) and SHA256SUMS of every file; it prints the tarball's own SHA-256,
# to cite with it. Of the quick pipeline: make archive RESULTS=results/quick FIGURES=results/quick/figures
# REPORT=results/quick/report/index.html. make verify-archive FILE=<tar.gz> [SHA256=<hex>] checks every file.
ARCHIVE ?= reproduction-$(shell git rev-parse --short HEAD 2>/dev/null || echo unknown).tar.gz
REPORT  ?= paper/build/index.html
ARCHIVE_PACKAGES := $(DEB_PACKAGES) libhdf5-103-1 libgomp1 python3-paraview slurm-wlm munge
archive:
	$(PY) tools/archive.py create --results $(RESULTS) --figures $(FIGURES) --report $(REPORT) --out $(ARCHIVE) \
	  --packages $(ARCHIVE_PACKAGES)
verify-archive:
	@[ -n "$(FILE)" ] || { echo "make verify-archive: give the archive, FILE=<file.tar.gz> [SHA256=<hex>]"; exit 2; }
	$(PY) tools/archive.py verify $(FILE) $(if $(SHA256),--sha256 $(SHA256))

# Our HDF5 + XDMF snapshots opened by ParaView's own XDMF reader (Debian python3-paraview, installed here if
# missing: ~90 MB, about a minute): a known series written by the library, exactly, and the hexagon's series of
# the last quick or full run if there is one (tests/test_paraview.py).
PV_SERIES = $(firstword $(patsubst %/,%,$(dir $(wildcard results/quick/H-fig4/*.xdmf results/H-fig4/*.xdmf))))
test-paraview: deps configure
	$(call apt_ensure,python3-paraview)
	cmake --build $(BUILD) -j $(JOBS) --target snapshot_sample
	$(PY) tests/test_paraview.py --sample $(BIN)/snapshot_sample $(if $(PV_SERIES),--series $(PV_SERIES))

# The Slurm launcher tested for real (tests/test_slurm.sh): a single-node Slurm of this machine
# (tools/slurm_single_node.sh; Debian slurm-wlm and munge, installed here if missing, ~40 packages, ~15 s), the
# quick pipeline through it into results/slurm (every driver run a job), the quick check, every driver run
# found as a Slurm job that exited 0, and the values identical to those of the last local quick run if there
# is one (results/quick). Needs root.
test-slurm: deps build-drivers
	$(call apt_ensure,slurm-wlm munge)
	tests/test_slurm.sh

# The library, the unit tests and the drivers built with AddressSanitizer and UndefinedBehaviorSanitizer
# (build-sanitize/, -O1): ctest and every driver's quick run under them; any report fails the make. Not part of
# `make test` (it costs ~3x a quick pipeline; the README gives the measured time).
SAN_BUILD := build-sanitize
sanitize: deps
	$(call ninja_only,$(SAN_BUILD))
	cmake -S . -B $(SAN_BUILD) $(CMAKE_GENERATOR_FLAGS) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-O1 -DSPH_SANITIZE=ON
	cmake --build $(SAN_BUILD) -j $(JOBS)
	cd $(SAN_BUILD) && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j $(JOBS)
	ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 OMP_NUM_THREADS=1 \
	  $(MAKE) --no-print-directory -j $(NCORES) BUILD=$(SAN_BUILD) RESULTS=results/sanitize DRIVER_FLAGS=--quick results
	@echo "make sanitize: ctest and every driver's quick run clean under ASan + UBSan"

# Benchmarks: Google Benchmark micro-benchmarks (results/bench/micro.json) and every scene benchmark in
# BENCH_DRIVERS (experiments/targets.mk), each writing results/bench/<name>.csv with the columns
# scene,variant,particles,steps,threads,wall_s,particle_steps_per_s,error_name,error; merged into
# results/bench.csv. The files merged are named from BENCH_DRIVERS, not found by $(wildcard), which Make
# would expand before the runs (an empty bench.csv on a fresh clone) and which would also pick up the
# drivers' values_*.csv.
bench: deps build
	cmake --build $(BUILD) --target micro_bench -j $(JOBS)
	@mkdir -p results/bench
	$(BIN)/micro_bench --benchmark_out=results/bench/micro.json --benchmark_out_format=json
	$(foreach b,$(BENCH_DRIVERS),$(BIN)/$(b) --out results/bench &&) true
	@awk '/^#/ {next} { if (seen[FILENAME]++ == 0 && hdr++ > 0) next; print }' \
	  $(foreach b,$(BENCH_DRIVERS),results/bench/$(b).csv) /dev/null > results/bench.csv
	@echo "make bench: results/bench.csv"; column -s, -t < results/bench.csv || cat results/bench.csv

# A speed-up against another revision, measured in one sitting (tools/bench_ab.py): the scene benchmarks of
# BASE (built in a clone under /tmp/bench_ab) and of this checkout, alternated AB_ROUNDS times; writes
# results/bench_ab.csv with the medians of both and their ratio. Throughputs of different sittings do not
# compare on this shared machine. E.g. make bench-ab BASE=fc0635a AB_ARGS='bench_gray_scenes=--scenes rings'
# AB_CMAKE_ARGS builds both sides with other CMake arguments, ours in build-ab/: e.g. an AVX2 build on an AVX-512
# host, AB_CMAKE_ARGS='-DSPH_NATIVE=OFF -DCMAKE_CXX_FLAGS=-march=native\ -mno-avx512f'.
BASE       ?=
AB_ROUNDS  ?= 3
AB_BENCHES ?= bench_gray_scenes,bench_hexagon
AB_ARGS    ?=
AB_CMAKE_ARGS ?=
comma := ,
bench-ab: deps configure
	@[ -n "$(BASE)" ] || { echo "make bench-ab: give the revision to compare against, BASE=<rev>"; exit 2; }
	cmake --build $(BUILD) -j $(JOBS) --target $(subst $(comma), ,$(AB_BENCHES))
	$(PY) tools/bench_ab.py --base $(BASE) --rounds $(AB_ROUNDS) --benches $(AB_BENCHES) \
	  $(if $(AB_ARGS),--args '$(AB_ARGS)') $(if $(AB_CMAKE_ARGS),--cmake-args '$(AB_CMAKE_ARGS)')

# PySPH on its own rings example (Debian python3-pysph; its Depends bring cython3, build-essential and
# python3-all-dev, which it needs to compile its kernels at the first run) and LAMMPS MACHDYN's smd/ulsph on our
# rings (PEER_THREADS MPI ranks) against our rings of the same layout: the same PEER_STEPS, OMP_NUM_THREADS=PEER_THREADS,
# one after the other (tools/bench_peer.py says what is timed). Writes results/bench/peer.csv (a row per code and
# the ratio rows ratio_ours_over_pysph, ratio_ours_over_lammps and ratio_ours_over_lammps_per_force_eval, whose
# particle_steps_per_s is the ratio) and merges it into results/bench.csv.
PEER_STEPS   ?= 600
PEER_THREADS ?= 2
bench-peer: deps configure
	$(call apt_ensure,python3-pysph)
	tools/peers/build_machdyn.sh
	cmake --build $(BUILD) --target bench_gray_scenes peer_rings -j $(JOBS)
	$(PY) tools/bench_peer.py --steps $(PEER_STEPS) --threads $(PEER_THREADS) --ours $(BIN)/bench_gray_scenes \
	  --pysph-python $(PY) --out results/bench --bench-csv results/bench.csv

# Independent codes on our scenes (issue 44; tools/peers/run_peers.py, one module tools/peers/scene_<scene>.py per
# scene): PySPH's implementation of Gray 2001 (Debian python3-pysph) and LAMMPS's MACHDYN (smd/ulsph, smd/tlsph,
# built as a plugin of Debian's lmp by tools/peers/build_machdyn.sh, ~1 min) run our layouts
# (build/bin/peer_<scene> --action layout) with our settings, their traces measured by our functions
# (--action measure), beside our own drivers at the same settings: results/peers/<scene>.csv (every run) and
# compare.csv (published | ours | peer | theory, and the speed per force evaluation). A case that is done is
# not rerun (its runs.csv); PEERS_FLAGS='--scenes plate --cases mu0.6 --force' selects. The first PySPH run
# compiles its kernels (~1-3 min, cached in ~/.pysph). make peers-quick: a few steps of every code path into
# results/peers-quick (part of make test; apart from results/quick, which test-slurm compares with its own quick
# run), measuring nothing.
PEER_THREADS_RUN ?= 1
PEERS_FLAGS ?=
peers: deps build
	$(call apt_ensure,python3-pysph)
	tools/peers/build_machdyn.sh
	$(PY) tools/peers/run_peers.py --build $(BUILD) --out $(RESULTS)/peers --threads $(PEER_THREADS_RUN) $(PEERS_FLAGS)
# make studies (issue 46 item 2): the paper's unstated choices, one at a time, each a run job of its own
# (tools/studies.py says which), and the open rows' values under each in results/studies/<study>_sensitivity.csv.
# Outside make figures (the plate study: 21 jobs per choice, 13-40 min of one core each choice, its eight about 1.5 h on 2
# cores); an interrupted one resumes.
studies: deps build
	$(PY) tools/studies.py --bin $(BIN) --out $(RESULTS)/studies --jobs $(JOBS) $(STUDIES_FLAGS)

peers-quick: deps build
	$(call apt_ensure,python3-pysph)
	tools/peers/build_machdyn.sh
	$(PY) tools/peers/run_peers.py --build $(BUILD) --out results/peers-quick --quick --force

# The reproduction report (HTML; paper/build_report.py says why not LaTeX).
# The check runs first; a FAIL does not stop the report, which shows it.
paper:
	-$(PY) reference/check.py --results $(RESULTS) $(CHECK_FLAGS) > /dev/null
	$(PY) paper/build_report.py --results $(RESULTS) --figures $(FIGURES) --reference reference --out paper/build/index.html

clean:
	rm -rf $(BUILD) results figures paper/build
