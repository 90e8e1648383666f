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
# shellcheck source=scripts/slurm/submit_common.sh
source "$here/submit_common.sh"
parse_submit_args "$0" "file of impacts" "$@"
data="$input" work="$out" fit="$merged"
mkdir -p "$work/slurm-logs"

array=$(sbatch --parsable --array="0-$((shards - 1))" --cpus-per-task="$cpus" \
    --job-name=planarbench-impacts --output="$work/slurm-logs/shard-%a.out" \
    --export=ALL "${extra[@]}" "$here/impacts_shard.sbatch" "$bin" "$data" "$shards" "$work")
array="${array%%;*}"
merge=$(sbatch --parsable --dependency="afterok:$array" --cpus-per-task=1 \
    --job-name=planarbench-impacts-merge --output="$work/slurm-logs/merge.out" \
    --export=ALL "${extra[@]}" "$here/impacts_merge.sbatch" "$bin" "$work" "$data" "$fit")
merge="${merge%%;*}"
echo "shards $array"
echo "merge $merge"
