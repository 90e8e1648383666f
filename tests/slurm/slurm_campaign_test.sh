#!/usr/bin/env bash
# A campaign on a real single-node Slurm (issue 14): starts slurmctld, slurmd
# and munged on localhost (scripts/slurm/local_slurm.sh; exit 77 = skipped
# when this machine cannot: not root, packages missing), then
#  1. runs the campaign on this machine as one shard and merges it;
#  2. submits it as a 4-task job array with the merge as a dependent job
#     (scripts/slurm/submit.sh) and checks the merged file holds the same
#     datasets, bit for bit (tests/python/dataset_hashes.py);
#  3. submits it again, kills shard 0 with SIGKILL once it has written its
#     first checkpoint, checks `campaign merge` then fails naming the missing
#     runs, resubmits shard 0 alone and checks the merge completes with no
#     duplicate and no lost run, bit-identical to step 1;
#  4. fits measured impacts (issue 23: a small file written by
#     tests/impacts/write_mat.py) as 3 shards on Slurm with the merge after
#     them (scripts/slurm/submit_impacts.sh) and checks the fit file holds the
#     datasets of the same fit in one process, bit for bit.
# Nothing is left running: the cluster is stopped on every exit.
#   slurm_campaign_test.sh PLANARBENCH SOURCE_DIR WORK_DIR
set -euo pipefail
bin="$(realpath "$1")" src="$(realpath "$2")" work="$3"
slurm="$src/scripts/slurm"
campaign="$src/tests/data/campaigns/slurm_small.toml"
hashes="/usr/bin/python3 $src/tests/python/dataset_hashes.py"
export PLANARBENCH="$bin" PLANARBENCH_CASES_DIR="$src/cases" CPUS_PER_TASK=1

rm -rf "$work"
mkdir -p "$work"
work="$(realpath "$work")"
# a short state folder: slurmstepd's sockets live there (108-byte socket paths)
state="$(mktemp -d /tmp/pbslurm.XXXXXX)"
cleanup() { bash "$slurm/local_slurm.sh" stop "$state" >/dev/null 2>&1 || true; rm -rf "$state"; }
trap cleanup EXIT
set +e
bash "$slurm/local_slurm.sh" start "$state"
rc=$?
set -e
[[ $rc -eq 0 ]] || exit "$rc"  # 77: skipped, with the reason printed by start
eval "$(bash "$slurm/local_slurm.sh" env "$state")"

fail() { echo "FAIL: $*"; exit 1; }
job_of() { awk -v k="$1" '$1 == k { print $2 }'; }

echo "== 1. one machine, one shard"
"$bin" campaign run "$campaign" --out "$work/one" --jobs 2 -q
"$bin" campaign merge "$work/one" --out "$work/one.h5" -q

echo "== 2. Slurm: 4 shards and the merge after them"
# the shards run in process (--isolation none): step 1 ran each run in a
# process of its own (the default), so the comparison below also checks
# that isolation gives the same bits, and the shards' sanitizer processes do
# not each start ~100 children (issue 24; CI time)
export CAMPAIGN_RUN_ARGS="--isolation none"
ids="$(bash "$slurm/submit.sh" "$campaign" 4 "$work/four" "$work/four.h5")"
echo "$ids"
merge="$(job_of merge <<<"$ids")"
bash "$slurm/wait_job.sh" "$merge" 300 || fail "the merge job did not end in 300 s"
[[ -f "$work/four.h5" ]] || { cat "$work/four/slurm-logs/"*.out; fail "no merged file"; }
$hashes same "$work/one.h5" "$work/four.h5" || fail "4 shards on Slurm differ from one shard"

echo "== 3. Slurm: shard 0 killed mid-run (SIGKILL), then resubmitted"
export CAMPAIGN_RUN_ARGS="--checkpoint-runs 1 --isolation none"
ids="$(bash "$slurm/submit.sh" "$campaign" 4 "$work/killed" "$work/killed.h5")"
array="$(job_of shards <<<"$ids")"
merge="$(job_of merge <<<"$ids")"
for _ in $(seq 600); do
    compgen -G "$work/killed/*.shard-0-of-4.part-*.h5" >/dev/null && break
    sleep 0.1
done
compgen -G "$work/killed/*.shard-0-of-4.part-*.h5" >/dev/null || fail "shard 0 wrote no checkpoint in 60 s"
scancel --signal=KILL --batch "${array}_0"
bash "$slurm/wait_job.sh" "$array" 300 || fail "the shards did not end in 300 s"
# the merge waits for a shard that failed: it never runs
scancel "$merge" || true
set +e
out="$("$bin" campaign merge "$work/killed" --out "$work/killed.h5" 2>&1)"
rc=$?
set -e
echo "$out" | head -5
[[ $rc -ne 0 ]] || fail "shard 0 was killed after it had finished: nothing was tested (make the campaign longer)"
grep -q "runs are missing" <<<"$out" || fail "merge did not say which runs are missing"
grep -q "runs are missing: .*run [0-9]*: " <<<"$out" || fail "merge did not name the missing runs"
[[ ! -e "$work/killed.h5" ]] || fail "a failed merge left a file"
# resubmitted, shard 0 runs only what it had not finished
sbatch --parsable --wait --array=0 --cpus-per-task=1 --output="$work/killed/slurm-logs/resubmit-%a.out" \
    "$slurm/shard.sbatch" "$bin" "$campaign" 4 "$work/killed" >/dev/null
grep -q "already in" "$work/killed/slurm-logs/resubmit-0.out" || fail "the resubmitted shard did not report a resume"
cat "$work/killed/slurm-logs/resubmit-0.out" | head -1
"$bin" campaign merge "$work/killed" --out "$work/killed.h5"
$hashes same "$work/one.h5" "$work/killed.h5" || fail "the resumed campaign differs from one shard"

echo "== 4. Slurm: a fit of measured impacts as 3 shards and the merge after them"
/usr/bin/python3 "$src/tests/impacts/write_mat.py" "$work/impacts.mat" 60 4 0.6 0.2 --models
export IMPACTS_FIT_ARGS="--engine box2d,reference_exact --folds 2 --max-evaluations 4 -q"
# shellcheck disable=SC2086
"$bin" impacts fit --data "$work/impacts.mat" --out "$work/impacts_one.h5" $IMPACTS_FIT_ARGS
ids="$(bash "$slurm/submit_impacts.sh" "$work/impacts.mat" 3 "$work/impacts" "$work/impacts_three.h5")"
echo "$ids"
merge="$(job_of merge <<<"$ids")"
bash "$slurm/wait_job.sh" "$merge" 300 || fail "the impacts merge job did not end in 300 s"
[[ -f "$work/impacts_three.h5" ]] || { cat "$work/impacts/slurm-logs/"*.out; fail "no merged fit file"; }
$hashes same "$work/impacts_one.h5" "$work/impacts_three.h5" || fail "3 impact shards on Slurm differ from one process"
echo "PASS"
