#!/usr/bin/env bash
# wait_job.sh JOBID [TIMEOUT_S]
# Wait until job JOBID (for an array: all of its tasks) has left the queue,
# i.e. is no longer pending/running/completing/suspended/etc.  Uses squeue
# only (no accounting => no sacct).  Needs SLURM_CONF in the environment for
# the local test cluster (eval "$(local_slurm.sh env STATE_DIR)").
# Exit: 0 = gone, 1 = timeout (job still queued), 2 = usage/squeue error.
set -euo pipefail

[[ $# -ge 1 && $# -le 2 && "$1" =~ ^[0-9]+$ ]] || {
    echo "usage: $0 JOBID [TIMEOUT_S=600]" >&2
    exit 2
}
JOBID="$1"
TIMEOUT="${2:-600}"
# Every state in which a job still occupies the queue (all but the final
# COMPLETED/FAILED/CANCELLED/TIMEOUT/... ones, which squeue -j would otherwise
# also list until MinJobAge expires).
ACTIVE=PENDING,RUNNING,SUSPENDED,COMPLETING,CONFIGURING,RESIZING,REQUEUED,REQUEUE_FED,REQUEUE_HOLD,SPECIAL_EXIT,STAGE_OUT,STOPPED,SIGNALING,RESV_DEL_HOLD

t0=$SECONDS
errors=0
while :; do
    if out="$(squeue -h -j "$JOBID" -t "$ACTIVE" -o %i 2>&1)"; then
        errors=0
        [[ -z "$out" ]] && exit 0
    elif [[ "$out" == *"Invalid job id"* ]]; then
        exit 0 # already purged from slurmctld (older than MinJobAge)
    else
        # Transient controller hiccup: tolerate a few, then give up.
        if ((++errors > 10)); then
            echo "wait_job: squeue keeps failing: $out" >&2
            exit 2
        fi
    fi
    if ((SECONDS - t0 >= TIMEOUT)); then
        echo "wait_job: job $JOBID still queued after ${TIMEOUT}s:" >&2
        squeue -j "$JOBID" -t "$ACTIVE" >&2 || true
        exit 1
    fi
    sleep 0.5
done
