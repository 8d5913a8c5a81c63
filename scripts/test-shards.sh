#!/usr/bin/env bash
# Runs a GoogleTest binary at most JOBS processes at a time, each writing DIR/gtest-<job>.json
# and DIR/gtest-<job>.log; prints every log and exits 1 when any job fails.
#
# The jobs, taken from one queue by whichever core is free: first every test named in
# HEAVY_LIST on its own, in the list's order (slowest first), then the remaining tests as SHARDS
# shards (GoogleTest's own sharding). GoogleTest deals tests to shards round-robin, so the dozen
# heavy tests (tens of seconds each under ASan) piled up in whichever shard they fell into and
# left the other core idle for minutes; longest-first on their own, then small shards to fill
# the gaps, both cores finish within about one small shard of each other. Small shards rather
# than one: more processes would rebuild per-process caches (the default bone library, 13 s
# under ASan) for little gain.
#
# HEAVY_LIST: one full test name a line (# comments and blank lines ignored). A name that
# matches no test fails the run, so the list cannot silently go stale; regenerate it from a run's
# reports with `node scripts/gtest-summary.mjs --slowest 15 DIR/gtest-*.json`.
#
# Usage: scripts/test-shards.sh BINARY DIR JOBS SHARDS [HEAVY_LIST]   (environment passed through)
set -euo pipefail

if [[ $# -lt 4 || $# -gt 5 ]]; then
    echo "usage: $0 BINARY DIR JOBS SHARDS [HEAVY_LIST]" >&2
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
heavy=()
if [[ $# -eq 5 ]]; then
    mapfile -t heavy < <(sed -e 's/#.*//' -e 's/[[:space:]]//g' -e '/^$/d' "$5")
fi
# The shards run everything but the heavy tests.
rest_filter="-$(IFS=:; echo "${heavy[*]}")"

run_job() {
    local job=$1
    if [[ $job == heavy-* ]]; then
        "$binary" --gtest_brief=1 --gtest_filter="${heavy[${job#heavy-}]}" \
            --gtest_output="json:$dir/gtest-$job.json" >"$dir/gtest-$job.log" 2>&1
    else
        GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=${job#shard-} \
            "$binary" --gtest_brief=1 --gtest_filter="$rest_filter" \
            --gtest_output="json:$dir/gtest-$job.json" >"$dir/gtest-$job.log" 2>&1
    fi
}
export -f run_job
export binary dir shards rest_filter
# Bash cannot export arrays: each job reads the list again from this string.
heavy_lines=$(printf '%s\n' "${heavy[@]}")
export heavy_lines

job_names=()
for i in "${!heavy[@]}"; do job_names+=("heavy-$i"); done
for i in $(seq 0 $((shards - 1))); do job_names+=("shard-$i"); done

status=0
printf '%s\n' "${job_names[@]}" |
    xargs -P "$jobs" -I{} bash -c 'mapfile -t heavy <<<"$heavy_lines"; run_job {}' || status=1
for job in "${job_names[@]}"; do
    # xargs stops starting jobs when one is killed by a signal: say which never ran.
    cat "$dir/gtest-$job.log" 2>/dev/null || { echo "test-shards.sh: $job did not run"; status=1; }
done
for i in "${!heavy[@]}"; do
    if grep -q '"tests": 0,' "$dir/gtest-heavy-$i.json" 2>/dev/null; then
        echo "test-shards.sh: the heavy list names ${heavy[$i]}, which matches no test" >&2
        status=1
    fi
done
exit $status
