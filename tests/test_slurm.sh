#!/usr/bin/env bash
# make test-slurm (issue 17): the quick pipeline with every driver run sent to a single-node Slurm of this
# machine (make LAUNCH=slurm), then: the quick check passes; the Slurm controller's log shows one job per driver
# run, each exited 0; and if a local quick run is there (results/quick), every value is the same (tools/
# compare_results.py: bit for bit; the same binaries, one thread each).
set -euo pipefail
cd "$(dirname "$0")/.."
PY=/usr/bin/python3
export SPH_SLURM_DIR=${SPH_SLURM_DIR:-/tmp/sph-slurm}
# Stop on exit (pass or fail) the Slurm daemons this test starts; an instance that was already up is left up.
pid=$SPH_SLURM_DIR/run/slurmctld.pid
if [ -f "$pid" ] && kill -0 "$(cat "$pid")" 2> /dev/null; then
  echo "test-slurm: a single-node Slurm is already up; it stays up"
else
  trap 'tools/slurm_single_node.sh stop' EXIT
fi
tools/slurm_single_node.sh start
export SLURM_CONF=$SPH_SLURM_DIR/slurm.conf
LOG=$SPH_SLURM_DIR/log/slurmctld.log
before=$(grep -c "_slurm_rpc_allocate_resources JobId=" "$LOG" || true)
# One job per driver invocation of every target, and one per simulation run of the split targets (list-runs: the
# quick runs, as the drivers list them).
rm -rf results/slurm
runs=$(( $(make -s list-targets | grep -v '^BENCH_DRIVERS' | awk -F';' '{n += split($2, d, " ")} END {print n}') + \
         $(make -s RESULTS=results/slurm DRIVER_FLAGS=--quick list-runs | awk -F';' '{n += split($2, d, " ")} END {print n + 0}') ))
start=$(date +%s)
OMP_NUM_THREADS=1 make --no-print-directory -j "$(nproc)" RESULTS=results/slurm FIGURES=results/slurm/figures \
  DRIVER_FLAGS=--quick LAUNCH=slurm plots
make --no-print-directory RESULTS=results/slurm CHECK_FLAGS=--quick check
elapsed=$(( $(date +%s) - start ))
ids=$(grep "_slurm_rpc_allocate_resources JobId=" "$LOG" | tail -n +$((before + 1)) | sed -E 's/.*JobId=([0-9]+).*/\1/')
jobs=$(echo "$ids" | grep -c . || true)
failed=0
for id in $ids; do
  grep -q "_job_complete: JobId=$id WEXITSTATUS 0" "$LOG" || { echo "test-slurm: job $id did not exit 0"; failed=$((failed + 1)); }
done
echo "test-slurm: $jobs Slurm jobs for $runs driver runs, $failed without a zero exit; $elapsed s"
[ "$jobs" -eq "$runs" ] || { echo "test-slurm: FAILED: $jobs jobs, expected one per driver run ($runs)"; exit 1; }
[ "$failed" -eq 0 ] || { echo "test-slurm: FAILED: jobs with a non-zero exit"; exit 1; }
if [ -f results/quick/check.csv ]; then
  $PY tools/compare_results.py results/quick results/slurm
fi
echo "test-slurm: passed"
