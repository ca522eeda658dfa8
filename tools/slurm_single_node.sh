#!/usr/bin/env bash
# A single-node Slurm on this machine (issue 17: `make test-slurm`), from Debian's slurm-wlm and munge, so that
# the pipeline's Slurm launcher (make LAUNCH=slurm) is tested for real: munged, slurmctld and slurmd started by
# hand (no systemd needed), one partition `local` holding this node with the CPUs and memory that `slurmd -C`
# reports. Everything of this instance lives under $SPH_SLURM_DIR (default /tmp/sph-slurm): its slurm.conf, state,
# spool, logs and pid files; the clients find it through SLURM_CONF=$SPH_SLURM_DIR/slurm.conf.
#   tools/slurm_single_node.sh start    configure and start (waits until the node is idle); idempotent
#   tools/slurm_single_node.sh stop     stop the three daemons of this instance
#   tools/slurm_single_node.sh status   sinfo of this instance
# Needs root (munge's key and run directory, slurmd's job launch); `make test-slurm` installs the packages.
# On a real cluster none of this is used: the site's slurm.conf is, and make LAUNCH=slurm only calls srun.
set -euo pipefail
DIR=${SPH_SLURM_DIR:-/tmp/sph-slurm}
CONF=$DIR/slurm.conf
export SLURM_CONF=$CONF

running() { [ -f "$1" ] && kill -0 "$(cat "$1")" 2>/dev/null; }

start() {
  [ "$(id -u)" -eq 0 ] || { echo "slurm_single_node: needs root (munge key, slurmd)"; exit 1; }
  for c in munged slurmctld slurmd srun sinfo; do
    command -v $c >/dev/null || { echo "slurm_single_node: $c missing: apt-get install slurm-wlm munge"; exit 1; }
  done
  mkdir -p "$DIR"/{state,spool,log,run}
  # munge: the package creates the key; its daemon runs as the munge user with its socket under /run/munge.
  if [ ! -s /etc/munge/munge.key ]; then
    dd if=/dev/urandom bs=1 count=1024 of=/etc/munge/munge.key 2>/dev/null
  fi
  chown munge:munge /etc/munge/munge.key && chmod 400 /etc/munge/munge.key
  mkdir -p /run/munge /var/lib/munge /var/log/munge && chown munge:munge /run/munge /var/lib/munge /var/log/munge
  if ! pgrep -x munged >/dev/null; then
    runuser -u munge -- munged
  fi
  local host node
  host=$(hostname -s)
  node=$(slurmd -C | sed -n 1p)  # NodeName=<host> CPUs=... RealMemory=...
  cat > "$CONF" <<EOF
# Written by tools/slurm_single_node.sh: a single-node Slurm for make test-slurm.
ClusterName=sph-local
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$DIR/state
SlurmdSpoolDir=$DIR/spool
SlurmctldPidFile=$DIR/run/slurmctld.pid
SlurmdPidFile=$DIR/run/slurmd.pid
SlurmctldLogFile=$DIR/log/slurmctld.log
SlurmdLogFile=$DIR/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
ReturnToService=2
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SlurmctldPort=6817
SlurmdPort=6818
$node State=UNKNOWN
PartitionName=local Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
  running "$DIR/run/slurmctld.pid" || slurmctld -f "$CONF"
  running "$DIR/run/slurmd.pid" || slurmd -f "$CONF"
  for _ in $(seq 60); do
    state=$(sinfo -h -o %T 2>/dev/null | head -1 || true)
    case "$state" in idle|mixed|allocated) echo "slurm_single_node: up ($host: $node; SLURM_CONF=$CONF)"; return 0;; esac
    sleep 1
  done
  echo "slurm_single_node: the node did not come up (state '$state'); logs:"; tail -20 "$DIR"/log/*.log
  exit 1
}

stop() {
  for d in slurmd slurmctld; do
    if running "$DIR/run/$d.pid"; then kill "$(cat "$DIR/run/$d.pid")"; fi
  done
  echo "slurm_single_node: stopped (munged left running)"
}

case "${1:-}" in
  start) start ;;
  stop) stop ;;
  status) sinfo ;;
  *) echo "usage: $0 start|stop|status"; exit 2 ;;
esac
