#!/usr/bin/env bash
# Runs every libFuzzer target BUILD_DIR/fuzz_<name> for SECONDS on a temporary copy of its seed
# corpus fuzz/corpus/<name>, so runs never add files to the repository. Exits 1 when any target
# crashes, hangs (> 10 s on one input, FUZZ_TIMEOUT), runs out of memory or trips a sanitizer;
# the failing inputs are copied to BUILD_DIR/fuzz-artifacts/. Add them to the corpus once fixed. Each
# target's summary line gives what docs/FUZZING.md records: executions, coverage (cov, ft) and
# the corpus size at the end; the full logs stay in BUILD_DIR/fuzz-logs/.
#
# Usage: scripts/fuzz.sh BUILD_DIR SECONDS [TARGET...]   (TARGET: e.g. lsystem; default all)
# FUZZ_JOBS=N runs up to N targets at once (default 1), each for SECONDS; FUZZ_TIMEOUT=S makes an
# input slower than S seconds a finding (default 10).
set -euo pipefail

if [[ $# -lt 2 ]]; then
    echo "usage: $0 BUILD_DIR SECONDS [TARGET...]" >&2
    exit 2
fi
build=$1
seconds=$2
shift 2
if ! [[ $seconds =~ ^[0-9]+$ ]] || [[ $seconds -lt 1 ]]; then
    echo "fuzz.sh: SECONDS must be a positive whole number, got '$seconds'" >&2
    exit 2
fi
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

shopt -s nullglob
targets=()
if [[ $# -gt 0 ]]; then
    for name in "$@"; do
        bin="$build/fuzz_${name#fuzz_}"
        if ! [[ -f $bin && -x $bin ]]; then
            echo "fuzz.sh: no fuzz target $bin" >&2
            exit 2
        fi
        targets+=("$bin")
    done
else
    for bin in "$build"/fuzz_*; do
        [[ -f $bin && -x $bin ]] && targets+=("$bin")
    done
fi
if [[ ${#targets[@]} -eq 0 ]]; then
    echo "fuzz.sh: no fuzz_* executables in $build (configure with -DRAMUS_BUILD_FUZZ=ON)" >&2
    exit 1
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/ramus-fuzz.XXXXXX")
trap 'rm -rf "$work"' EXIT

status=0
logs="$build/fuzz-logs"
mkdir -p "$logs"
# Fuzzes one target; prints its summary line, or the end of its log on failure (returns 1).
fuzz_one() {
    local bin=$1
    local name corpusName seeds corpus artifacts log runs last cov ft corp
    name=$(basename "$bin")
    corpusName=${name#fuzz_}
    seeds="$root/fuzz/corpus/$corpusName"
    corpus="$work/corpus-$corpusName"
    artifacts="$work/artifacts-$corpusName"
    mkdir -p "$corpus" "$artifacts"
    if [[ -d $seeds ]]; then
        cp -R "$seeds"/. "$corpus"/
    else
        echo "fuzz.sh: warning: no seed corpus $seeds; starting empty" >&2
    fi
    log="$logs/$name.log"
    echo "fuzz.sh: $name for ${seconds}s (seeds: fuzz/corpus/$corpusName)"
    if ! "$bin" -max_total_time="$seconds" -timeout="${FUZZ_TIMEOUT:-10}" -rss_limit_mb=2048 \
        -artifact_prefix="$artifacts/" -print_final_stats=1 "$corpus" >"$log" 2>&1; then
        echo "fuzz.sh: $name FAILED; end of its log:" >&2
        tail -n 60 "$log" >&2
        mkdir -p "$build/fuzz-artifacts"
        cp "$artifacts"/* "$build/fuzz-artifacts/" 2>/dev/null || true
        echo "fuzz.sh: failing inputs copied to $build/fuzz-artifacts/" >&2
        return 1
    fi
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    # The last status line, e.g. "#123456 DONE cov: 1234 ft: 5678 corp: 321/45Kb ...".
    last=$(grep -E '^#[0-9]+' "$log" | tail -n 1 || true)
    cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
    ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
    corp=$(sed -n 's/.* corp: \([0-9]*\/[0-9A-Za-z]*\).*/\1/p' <<<"$last")
    echo "fuzz.sh: $name ok (${runs:-?} inputs, cov ${cov:-?}, ft ${ft:-?}," \
        "corpus ${corp:-?}; log $log)"
}

jobs=${FUZZ_JOBS:-1}
if ! [[ $jobs =~ ^[1-9][0-9]*$ ]]; then
    echo "fuzz.sh: FUZZ_JOBS must be a positive whole number, got '$jobs'" >&2
    exit 2
fi
pids=()
for bin in "${targets[@]}"; do
    while [[ $(jobs -rp | wc -l) -ge $jobs ]]; do sleep 0.2; done
    fuzz_one "$bin" &
    pids+=("$!")
done
for pid in "${pids[@]}"; do
    wait "$pid" || status=1
done
exit $status
