#!/usr/bin/env bash
# Start/stop a throw-away single-node Slurm cluster on localhost (for CTest).
#
#   local_slurm.sh start STATE_DIR   # write config, start munged+slurmctld+slurmd, wait for node idle
#   local_slurm.sh stop  STATE_DIR   # stop what `start` started (by pid files), wait until gone
#   local_slurm.sh env   STATE_DIR   # print `export SLURM_CONF=...` for eval in a client shell
#
# Everything (config, munge key/socket, state, spool, logs, pid files) lives
# under STATE_DIR (except: if STATE_DIR is longer than 64 chars, the munge
# socket and slurmd spool go to a /tmp/local_slurm.XXXXXX dir, removed by
# stop); nothing is written under /etc.  Exit code 77 means "cannot
# run here" (not root, or slurm/munge not installed): use it as CTest's
# SKIP_RETURN_CODE.  Tested with Debian 12 packages slurm-wlm 22.05 + munge 0.5.15.
#
# Tunables (environment): LOCAL_SLURM_CTLD_PORT (16817), LOCAL_SLURM_SLURMD_PORT
# (16818), LOCAL_SLURM_START_TIMEOUT (30 s), LOCAL_SLURM_CLUSTER (planarbench).
set -euo pipefail

CLUSTER="${LOCAL_SLURM_CLUSTER:-planarbench}"
# Non-default ports so we never talk to (or clash with) a system Slurm on 6817/6818.
CTLD_PORT="${LOCAL_SLURM_CTLD_PORT:-16817}"
SLURMD_PORT="${LOCAL_SLURM_SLURMD_PORT:-16818}"
START_TIMEOUT="${LOCAL_SLURM_START_TIMEOUT:-30}"
# The node is always called "localhost" whatever the machine's hostname is;
# slurmd is told its name with -N, so /etc/hosts and `hostname` do not matter.
NODE=localhost

PATH="$PATH:/usr/sbin:/sbin"

usage() {
    echo "usage: $0 {start|stop|env} STATE_DIR" >&2
    exit 2
}

skip() { # CTest SKIP_RETURN_CODE
    echo "SKIP: $*"
    exit 77
}

# Exit 77 (skipped) if this machine cannot run the cluster at all.
check_can_run() {
    local b pkg
    for b in munged:munge munge:munge mungekey:munge slurmctld:slurmctld slurmd:slurmd \
        sinfo:slurm-client sbatch:slurm-client squeue:slurm-client scancel:slurm-client; do
        pkg="${b#*:}"
        b="${b%%:*}"
        command -v "$b" >/dev/null 2>&1 || skip "'$b' not found: install package '$pkg' (apt-get install -y slurm-wlm munge)"
    done
    # munged/slurmd must be root here: slurmd has to setuid to the job's user
    # and we run munged with our own key, which needs no munge system user.
    [[ "$(id -u)" -eq 0 ]] || skip "must run as root to start munged/slurmd (uid $(id -u))"
}

[[ $# -eq 2 ]] || usage
CMD="$1"
if [[ "$CMD" == start ]]; then
    check_can_run
    mkdir -p "$2"
elif [[ "$CMD" == stop && ! -d "$2" ]]; then
    exit 0 # nothing was ever started there
fi
STATE_DIR="$(cd "$2" && pwd -P)"

CONF="$STATE_DIR/slurm.conf"
MUNGE_DIR="$STATE_DIR/munge"
MUNGE_KEY="$MUNGE_DIR/munge.key"
MUNGE_PID="$STATE_DIR/run/munged.pid"
SLURMCTLD_PID="$STATE_DIR/run/slurmctld.pid"
SLURMD_PID="$STATE_DIR/run/slurmd.pid"
LOG_DIR="$STATE_DIR/log"
# Directory holding the unix sockets (munge socket, and slurmd's spool where
# slurmstepd creates NODE_JOBID.STEPID sockets).  It is STATE_DIR itself unless
# STATE_DIR is too long (see pick_sock_dir); the choice is recorded here.
SOCK_DIR_FILE="$STATE_DIR/sock_dir"

# ---------------------------------------------------------------- helpers

# pid from a pid file if that process is alive and is the expected program
# (guards against a stale pid file whose pid was reused by something else).
live_pid() { # pidfile comm-prefix
    local pid
    [[ -s "$1" ]] || return 1
    pid="$(tr -dc 0-9 <"$1")"
    [[ -n "$pid" ]] || return 1
    kill -0 "$pid" 2>/dev/null || return 1
    [[ "$(cat "/proc/$pid/comm" 2>/dev/null)" == "$2"* ]] || return 1
    echo "$pid"
}

# SIGTERM the given daemons (name:pidfile ...) at once, wait up to 10 s for all
# to exit, SIGKILL leftovers.  In parallel because each Slurm/munge daemon
# takes 1-2 s to notice SIGTERM (its threads poll about once per second).
stop_daemons() {
    local spec name pidfile pid i alive
    local -a pids=()
    for spec in "$@"; do
        name="${spec%%:*}"
        pidfile="${spec#*:}"
        if pid="$(live_pid "$pidfile" "$name")"; then
            kill -TERM "$pid" 2>/dev/null || true
            pids+=("$pid")
        fi
        rm -f "$pidfile"
    done
    ((${#pids[@]})) || return 0
    for ((i = 0; i < 200; i++)); do
        alive=()
        for pid in "${pids[@]}"; do
            if kill -0 "$pid" 2>/dev/null; then alive+=("$pid"); fi
        done
        ((${#alive[@]})) || return 0
        if ((i == 100)); then # 10 s grace over
            echo "local_slurm: pid(s) ${alive[*]} ignored SIGTERM, sending SIGKILL" >&2
            kill -KILL "${alive[@]}" 2>/dev/null || true
        fi
        sleep 0.1
    done
    echo "local_slurm: pid(s) ${alive[*]} still alive after SIGKILL" >&2
    return 1
}

sock_dir() {
    if [[ -s "$SOCK_DIR_FILE" ]]; then cat "$SOCK_DIR_FILE"; else echo "$STATE_DIR"; fi
}
munge_socket() { echo "$(sock_dir)/munge/munge.socket"; }
spool_dir() { echo "$(sock_dir)/spool"; }

# Trap: a unix socket path must fit in sun_path (108 bytes).  munged's socket
# and slurmstepd's step sockets ("SPOOL/localhost_<jobid>.<stepid>", up to 31
# chars after SPOOL/) both live below this directory; if STATE_DIR is longer
# than 64 chars, jobs would fail to launch ("Unix socket path ... is too long",
# job requeued held), so use a private short directory under /tmp instead.
pick_sock_dir() {
    local d="$STATE_DIR"
    if ((${#STATE_DIR} > 64)); then
        d="$(mktemp -d /tmp/local_slurm.XXXXXX)"
        chmod 0755 "$d"
    fi
    echo "$d" >"$SOCK_DIR_FILE"
}

dump_logs() {
    local f
    for f in "$LOG_DIR"/munged.log "$LOG_DIR"/slurmctld.log "$LOG_DIR"/slurmd.log "$LOG_DIR"/*.stderr; do
        [[ -s "$f" ]] || continue
        echo "===== $f (last 60 lines) =====" >&2
        tail -n 60 "$f" >&2
    done
}

do_env() {
    # SLURM_CONF is all a client needs: the munge socket is passed to the
    # slurm auth plugin through AuthInfo=socket=... inside slurm.conf.
    # MUNGE_SOCKET is only informational (for `munge -S "$MUNGE_SOCKET"`).
    echo "export SLURM_CONF='$CONF'"
    echo "export MUNGE_SOCKET='$(munge_socket)'"
    # Stale variables from an enclosing allocation would confuse sbatch/srun.
    echo "unset SLURM_JOB_ID SLURM_JOBID SLURM_CLUSTERS"
}

do_stop() {
    local sock d i jobs=()
    export SLURM_CONF="$CONF"
    # Cancel leftover jobs first: with proctrack/linuxproc, stopping slurmd
    # does not kill running job steps (slurmstepd is a separate process).
    if live_pid "$SLURMCTLD_PID" slurmctld >/dev/null && [[ -f "$CONF" ]]; then
        mapfile -t jobs < <(timeout 10 squeue -h -o %i 2>/dev/null || true)
        if ((${#jobs[@]})); then
            timeout 10 scancel --quiet "${jobs[@]}" 2>/dev/null || true
            for ((i = 0; i < 100; i++)); do
                [[ -z "$(timeout 5 squeue -h -t R,CG,S -o %i 2>/dev/null || true)" ]] && break
                sleep 0.1
            done
        fi
    fi
    stop_daemons slurmd:"$SLURMD_PID" slurmctld:"$SLURMCTLD_PID" munged:"$MUNGE_PID"
    sock="$(munge_socket)"
    rm -f "$sock" "$sock.lock"
    # Remove the short /tmp socket dir if we had to use one (only our own).
    d="$(sock_dir)"
    case "$d" in /tmp/local_slurm.??????) rm -rf "$d" ;; esac
    rm -f "$SOCK_DIR_FILE"
}

do_start() {
    local sock ncpu mem_mb state i t0 busy
    t0=$SECONDS
    # (check_can_run already ran: 77 if not root / packages missing.)

    # A previous run that was not stopped (crashed test): stop it first.
    do_stop

    # Fail clearly (not after a 30 s timeout) if someone else holds our ports.
    if command -v ss >/dev/null 2>&1; then
        busy="$(ss -Htlnp "( sport = :$CTLD_PORT or sport = :$SLURMD_PORT )" 2>/dev/null || true)"
        if [[ -n "$busy" ]]; then
            echo "local_slurm: port $CTLD_PORT or $SLURMD_PORT already in use (set LOCAL_SLURM_CTLD_PORT/LOCAL_SLURM_SLURMD_PORT):" >&2
            echo "$busy" >&2
            exit 1
        fi
    fi

    # --- directories ------------------------------------------------------
    # Fresh controller state and spool each start (no stale jobs/nodes), but
    # keep the munge key.
    rm -rf "$STATE_DIR/ctld" "$STATE_DIR/spool" "$LOG_DIR"
    pick_sock_dir
    sock="$(munge_socket)"
    mkdir -p "$STATE_DIR/ctld" "$(spool_dir)" "$STATE_DIR/run" "$LOG_DIR" "$MUNGE_DIR" "$(dirname "$sock")"
    # munged refuses a key/socket directory writable by group/other; it must
    # be world-searchable (0755) or non-root clients cannot reach the socket.
    chmod 0755 "$MUNGE_DIR" "$(dirname "$sock")"
    chmod 0755 "$STATE_DIR/run" "$LOG_DIR"

    # --- munge ------------------------------------------------------------
    if [[ ! -s "$MUNGE_KEY" ]]; then
        mungekey --create --keyfile="$MUNGE_KEY" --force >/dev/null
    fi
    # munged requires the key to be owned by its (effective) user and not
    # readable by group/other.
    chown root:root "$MUNGE_KEY"
    chmod 0400 "$MUNGE_KEY"
    # --force: munged checks that every directory on the paths of key/socket/
    # log/seed is not group/other-writable (e.g. a STATE_DIR under a 0775 build
    # tree); --force turns those checks into warnings and removes a stale socket.
    if ! munged --force --socket="$sock" --key-file="$MUNGE_KEY" \
        --log-file="$LOG_DIR/munged.log" --pid-file="$MUNGE_PID" \
        --seed-file="$MUNGE_DIR/munged.seed" 2>"$LOG_DIR/munged.stderr"; then
        cat "$LOG_DIR/munged.stderr" >&2
        skip "munged cannot run here: $(tail -n1 "$LOG_DIR/munged.stderr")"
    fi
    for ((i = 0; i < 50; i++)); do
        [[ -S "$sock" ]] && break
        sleep 0.1
    done
    if ! munge -n -S "$sock" 2>/dev/null | unmunge -S "$sock" >/dev/null 2>&1; then
        dump_logs
        do_stop
        skip "munged started but a munge/unmunge round trip failed"
    fi

    # --- slurm.conf -------------------------------------------------------
    ncpu="$(nproc)"
    # Modest RealMemory: half of MemTotal, capped at 4 GiB.  CR_CPU does not
    # treat memory as consumable, so this only has to be <= the real amount
    # (a bigger value would make slurmd register as invalid and drain).
    mem_mb="$(awk '/^MemTotal:/ {m=int($2/1024/2); if (m>4096) m=4096; if (m<100) m=100; print m}' /proc/meminfo)"

    # Empty plugstack so the packaged /etc/slurm/plugstack.conf(.d) is not used.
    : >"$STATE_DIR/plugstack.conf"

    # cgroup: proctrack/cgroup + task/cgroup need a writable cgroup hierarchy
    # and the cgroup plugins behave badly in containers/gVisor (hybrid v1 with
    # an emulated cgroupfs).  We do not need resource enforcement for tests, so
    # we track job processes via /proc (linuxproc) and do no task binding
    # (task/none).  Hence no cgroup.conf is required or read.
    cat >"$CONF" <<EOF
# Generated by $(basename "$0") -- single-node test cluster, do not edit.
ClusterName=$CLUSTER
# Controller on loopback; name(addr) so the hostname need not resolve.
SlurmctldHost=$NODE(127.0.0.1)
SlurmctldPort=$CTLD_PORT
SlurmdPort=$SLURMD_PORT
# Both daemons run as root (so jobs may run as any user, including root).
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
# Our private munged; clients read this from slurm.conf, no env var needed.
AuthInfo=socket=$sock
StateSaveLocation=$STATE_DIR/ctld
SlurmdSpoolDir=$(spool_dir)
SlurmctldPidFile=$SLURMCTLD_PID
SlurmdPidFile=$SLURMD_PID
SlurmctldLogFile=$LOG_DIR/slurmctld.log
SlurmdLogFile=$LOG_DIR/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
PlugStackConfig=$STATE_DIR/plugstack.conf
MpiDefault=none
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
# Allocate individual CPUs (not whole nodes) so several 1-CPU array tasks run
# at the same time on the node.
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
# Schedule sbatch jobs right away instead of batching submissions for up to
# 3 s (default): cuts submit->start latency from ~1-3 s to <= ~1 s.
SchedulerParameters=batch_sched_delay=0
# No mail (default /usr/bin/mail is absent and logs an error).
MailProg=/bin/true
# No slurmdbd/accounting: sacct will not work, use squeue/scontrol.
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
# A node that was DOWN comes back as soon as it registers with a valid config.
ReturnToService=2
# Use the configured CPUs/RealMemory even if slurmd detects different hardware
# (never drain the only node because of a mismatch).
SlurmdParameters=config_overrides
# Finished jobs are purged from slurmctld memory (and squeue -j) after 30 s.
MinJobAge=30
# Short timeouts: a dead daemon should be noticed quickly in tests.
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
KillWait=5
NodeName=$NODE NodeHostname=$NODE NodeAddr=127.0.0.1 CPUs=$ncpu RealMemory=$mem_mb State=UNKNOWN
PartitionName=main Nodes=$NODE Default=YES MaxTime=INFINITE State=UP OverSubscribe=NO
EOF

    # --- daemons ------------------------------------------------------------
    export SLURM_CONF="$CONF"
    # -c: cold start, ignore any saved job/node state (belt and braces, the
    # state dir was just wiped).  Both daemons daemonize and write pid files.
    if ! slurmctld -f "$CONF" -c >>"$LOG_DIR/slurmctld.stderr" 2>&1; then
        cat "$LOG_DIR/slurmctld.stderr" >&2
        dump_logs
        do_stop
        echo "local_slurm: slurmctld failed to start" >&2
        exit 1
    fi
    # -N: our node name is "localhost" regardless of `hostname`.
    if ! slurmd -f "$CONF" -N "$NODE" >>"$LOG_DIR/slurmd.stderr" 2>&1; then
        cat "$LOG_DIR/slurmd.stderr" >&2
        dump_logs
        do_stop
        echo "local_slurm: slurmd failed to start" >&2
        exit 1
    fi

    # --- wait until the node is idle ---------------------------------------
    state=""
    while ((SECONDS - t0 < START_TIMEOUT)); do
        state="$(timeout 5 sinfo -h -n "$NODE" -o %T 2>/dev/null || true)"
        [[ "$state" == idle ]] && break
        sleep 0.2
    done
    if [[ "$state" != idle ]]; then
        echo "local_slurm: node '$NODE' not idle after ${START_TIMEOUT}s (state: '${state:-no answer}')" >&2
        timeout 5 scontrol show node "$NODE" >&2 2>&1 || true
        dump_logs
        do_stop
        exit 1
    fi
    echo "local_slurm: cluster '$CLUSTER' up in $((SECONDS - t0))s, node $NODE idle ($ncpu CPUs); eval \"\$($0 env $STATE_DIR)\""
}

case "$CMD" in
start) do_start ;;
stop) do_stop ;;
env) do_env ;;
*) usage ;;
esac
