#!/usr/bin/env bash
# Runs a GoogleTest binary as SHARDS shards (GoogleTest's own sharding), at most JOBS at a time,
# each writing DIR/gtest-<i>.json and DIR/gtest-<i>.log; prints every log and exits 1 when any
# shard fails. More shards than cores balance the load: GoogleTest deals tests round-robin, so
# with one shard per core the few heavy tests (tens of seconds each under ASan) could pile up in
# one shard while the other core sat idle for minutes; small shards taken from a queue by
# whichever core is free finish within about one shard's time of each other.
#
# Usage: scripts/test-shards.sh BINARY DIR JOBS SHARDS   (the environment is passed through)
set -euo pipefail

if [[ $# -ne 4 ]]; then
    echo "usage: $0 BINARY DIR JOBS SHARDS" >&2
    exit 2
fi
binary=$(realpath "$1")
dir=$(realpath "$2")
jobs=$3
shards=$4
for n in "$jobs" "$shards"; do
    if ! [[ $n =~ ^[1-9][0-9]*$ ]]; then
        echo "test-shards.sh: JOBS and SHARDS must be positive whole numbers, got '$n'" >&2
        exit 2
    fi
done

run_shard() {
    local i=$1
    GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$i \
        "$binary" --gtest_brief=1 --gtest_output="json:$dir/gtest-$i.json" \
        >"$dir/gtest-$i.log" 2>&1
}
export -f run_shard
export binary dir shards

status=0
seq 0 $((shards - 1)) | xargs -P "$jobs" -I{} bash -c 'run_shard {}' || status=1
for i in $(seq 0 $((shards - 1))); do
    # xargs stops starting shards when one is killed by a signal: say which never ran.
    cat "$dir/gtest-$i.log" 2>/dev/null || { echo "test-shards.sh: shard $i did not run"; status=1; }
done
exit $status
