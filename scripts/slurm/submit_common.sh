#!/usr/bin/env bash
# Sourced by submit.sh and submit_impacts.sh: their shared command line
#   SCRIPT INPUT N OUT_DIR [MERGED.h5] [-- extra sbatch options]
# Sets input (realpath), shards, out, merged (default OUT_DIR.h5), bin (the
# planarbench binary: $PLANARBENCH, default this checkout's release build),
# cpus ($CPUS_PER_TASK, default 2) and extra (the sbatch options), or exits 2
# with a message. Call: parse_submit_args SCRIPT_PATH WHAT "$@" (WHAT names
# the input in messages, e.g. "campaign file").
parse_submit_args() {
    local script="$1" what="$2"
    shift 2
    local name root
    name="$(basename "$script")"
    root="$(cd "$(dirname "$script")/../.." && pwd)"
    if [[ $# -lt 3 ]]; then
        sed -n '2,/^set -euo/p' "$script" | sed '$d' >&2
        exit 2
    fi
    input="$(realpath "$1")"
    shards="$2"
    out="$(realpath -m "$3")"
    merged="$(realpath -m "${4:-$out.h5}")"
    shift 3
    [[ $# -gt 0 && "$1" != "--" ]] && shift
    [[ $# -gt 0 && "$1" == "--" ]] && shift
    extra=("$@")
    if ! [[ "$shards" =~ ^[1-9][0-9]*$ ]]; then
        echo "$name: N must be a positive integer (got '$shards')" >&2
        exit 2
    fi
    [[ -f "$input" ]] || { echo "$name: $input: no such $what" >&2; exit 2; }
    bin="$(realpath "${PLANARBENCH:-$root/build/release/apps/planarbench}")"
    [[ -x "$bin" ]] || { echo "$name: $bin is not an executable (build first, or set PLANARBENCH)" >&2; exit 2; }
    cpus="${CPUS_PER_TASK:-2}"
}
