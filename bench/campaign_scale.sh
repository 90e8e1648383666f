#!/usr/bin/env bash
# Times `campaign plan` and `campaign merge` of a 10,000-run campaign
# (bench/campaign_10k.toml) with hyperfine: the plan, and the merge of the
# files its 8 shards wrote (checkpoints of 64 runs: ~160 files). Issue 14's
# targets: plan < 1 s, merge < 10 s. Writes results/bench/campaign_scale.json
# (hyperfine's export) and prints hyperfine's summary.
#
#   bench/campaign_scale.sh [BUILD_DIR]     (default build/release)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build/release}"
bin="$build/apps/planarbench"
[[ -x "$bin" ]] || { echo "campaign_scale.sh: $bin missing: build first (scripts/build.sh release)" >&2; exit 2; }
command -v hyperfine >/dev/null || { echo "campaign_scale.sh: hyperfine missing (apt-get install hyperfine)" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p results/bench
"$bin" campaign plan bench/campaign_10k.toml --shards 8
echo "making the shards' files (8 shards, --jobs 2 each, one after the other) ..."
start=$SECONDS
for k in 0 1 2 3 4 5 6 7; do
    "$bin" campaign run bench/campaign_10k.toml --shard "$k/8" --out "$work/parts" --jobs 2 -q
done
echo "  $((SECONDS - start)) s; $(ls "$work/parts" | wc -l) files, $(du -sh "$work/parts" | cut -f1)"
hyperfine --warmup 1 --runs 5 --export-json results/bench/campaign_scale.json \
    -n plan "$bin campaign plan bench/campaign_10k.toml --shards 8 -q" \
    -n merge "$bin campaign merge $work/parts --out $work/merged.h5 -q"
ls -la "$work/merged.h5"
