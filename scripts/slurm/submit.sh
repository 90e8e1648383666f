#!/usr/bin/env bash
# Submits a campaign to Slurm: a job array of N shards, then the merge as a
# job that starts when every shard has ended well (afterok).
#
#   scripts/slurm/submit.sh CAMPAIGN.toml N OUT_DIR [MERGED.h5] [-- extra sbatch options]
#
# Each array task runs `planarbench campaign run CAMPAIGN --shard $SLURM_ARRAY_TASK_ID/N
# --out OUT_DIR --jobs $SLURM_CPUS_PER_TASK` (shard.sbatch); a task that is
# preempted, killed or times out leaves its finished runs in OUT_DIR, and
# resubmitting it (`sbatch --array=K ...`, or this script again) runs only
# what is missing. The merge job (merge.sbatch) writes MERGED (default
# OUT_DIR.h5) and fails, naming the missing runs, if any shard did not finish.
#
# Environment: PLANARBENCH (the binary; default build/release/apps/planarbench
# of this checkout), CPUS_PER_TASK (default 2: the engines of one shard run on
# that many threads), PLANARBENCH_CASES_DIR (case names; default the checkout's cases/),
# CAMPAIGN_RUN_ARGS (more options of `campaign run`, e.g. "--checkpoint-runs 16").
# Prints the two job ids: "shards JOBID" and "merge JOBID".
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
# shellcheck source=scripts/slurm/submit_common.sh
source "$here/submit_common.sh"
parse_submit_args "$0" "campaign file" "$@"
campaign="$input"
export PLANARBENCH_CASES_DIR="${PLANARBENCH_CASES_DIR:-$root/cases}"

# the plan first: a campaign file with an error fails here, not in N tasks
"$bin" campaign plan "$campaign" --shards "$shards" -q
mkdir -p "$out/slurm-logs"

array=$(sbatch --parsable --array="0-$((shards - 1))" --cpus-per-task="$cpus" \
    --job-name=planarbench-shards --output="$out/slurm-logs/shard-%a.out" \
    --export=ALL "${extra[@]}" "$here/shard.sbatch" "$bin" "$campaign" "$shards" "$out")
array="${array%%;*}"
merge=$(sbatch --parsable --dependency="afterok:$array" --cpus-per-task=1 \
    --job-name=planarbench-merge --output="$out/slurm-logs/merge.out" \
    --export=ALL "${extra[@]}" "$here/merge.sbatch" "$bin" "$out" "$merged")
merge="${merge%%;*}"
echo "shards $array"
echo "merge $merge"
