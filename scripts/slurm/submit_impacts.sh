#!/usr/bin/env bash
# Submits `planarbench impacts fit` to Slurm: a job array of N shards, each
# running its share of the fit's tasks (per model: one fit per
# cross-validation fold and one on the whole file) into WORK_DIR, then the
# merge as a job that starts when every shard has ended well (afterok).
#
#   scripts/slurm/submit_impacts.sh DATA.mat N WORK_DIR [FIT.h5] [-- extra sbatch options]
#
# Each array task runs `planarbench impacts fit --data DATA --shard
# $SLURM_ARRAY_TASK_ID/N --work WORK_DIR --jobs $SLURM_CPUS_PER_TASK`
# (impacts_shard.sbatch); a task that is killed keeps every task it finished
# (WORK_DIR/tasks/*.json) and resubmitting it runs only the missing ones. The
# merge job (impacts_merge.sbatch) writes FIT (default WORK_DIR.h5) and
# fails, naming the unfinished tasks, if any shard did not finish.
#
# Environment: PLANARBENCH (the binary; default build/release/apps/planarbench
# of this checkout), CPUS_PER_TASK (default 2), IMPACTS_FIT_ARGS (more options
# of `impacts fit`, the same for every shard, e.g. "--engine mujoco,ode
# --folds 5"). Prints the two job ids: "shards JOBID" and "merge JOBID".
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"

if [[ $# -lt 3 ]]; then
    sed -n '2,20p' "$0" >&2
    exit 2
fi
data="$(realpath "$1")"
shards="$2"
work="$(realpath -m "$3")"
fit="$(realpath -m "${4:-$work.h5}")"
shift 3
[[ $# -gt 0 && "$1" != "--" ]] && shift
[[ $# -gt 0 && "$1" == "--" ]] && shift
if ! [[ "$shards" =~ ^[1-9][0-9]*$ ]]; then
    echo "submit_impacts.sh: N must be a positive integer (got '$shards')" >&2
    exit 2
fi
[[ -f "$data" ]] || { echo "submit_impacts.sh: $data: no such file of impacts" >&2; exit 2; }
bin="$(realpath "${PLANARBENCH:-$root/build/release/apps/planarbench}")"
[[ -x "$bin" ]] || { echo "submit_impacts.sh: $bin is not an executable (build first, or set PLANARBENCH)" >&2; exit 2; }
cpus="${CPUS_PER_TASK:-2}"
mkdir -p "$work/slurm-logs"

array=$(sbatch --parsable --array="0-$((shards - 1))" --cpus-per-task="$cpus" \
    --job-name=planarbench-impacts --output="$work/slurm-logs/shard-%a.out" \
    --export=ALL "$@" "$here/impacts_shard.sbatch" "$bin" "$data" "$shards" "$work")
array="${array%%;*}"
merge=$(sbatch --parsable --dependency="afterok:$array" --cpus-per-task=1 \
    --job-name=planarbench-impacts-merge --output="$work/slurm-logs/merge.out" \
    --export=ALL "$@" "$here/impacts_merge.sbatch" "$bin" "$work" "$data" "$fit")
merge="${merge%%;*}"
echo "shards $array"
echo "merge $merge"
