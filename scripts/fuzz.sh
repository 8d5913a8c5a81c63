#!/usr/bin/env bash
# Runs every libFuzzer target BUILD_DIR/fuzz_<name> for SECONDS on a temporary copy of its seed
# corpus fuzz/corpus/<name>, so runs never add files to the repository. Exits 1 when any target
# crashes, hangs (> 10 s on one input), runs out of memory or trips a sanitizer; the failing
# inputs are copied to BUILD_DIR/fuzz-artifacts/. Add them to the corpus once fixed.
#
# Usage: scripts/fuzz.sh BUILD_DIR SECONDS
set -euo pipefail

if [[ $# -ne 2 ]]; then
    echo "usage: $0 BUILD_DIR SECONDS" >&2
    exit 2
fi
build=$1
seconds=$2
if ! [[ $seconds =~ ^[0-9]+$ ]] || [[ $seconds -lt 1 ]]; then
    echo "fuzz.sh: SECONDS must be a positive whole number, got '$seconds'" >&2
    exit 2
fi
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

shopt -s nullglob
targets=()
for bin in "$build"/fuzz_*; do
    [[ -f $bin && -x $bin ]] && targets+=("$bin")
done
if [[ ${#targets[@]} -eq 0 ]]; then
    echo "fuzz.sh: no fuzz_* executables in $build (configure with -DRAMUS_BUILD_FUZZ=ON)" >&2
    exit 1
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/ramus-fuzz.XXXXXX")
trap 'rm -rf "$work"' EXIT

status=0
for bin in "${targets[@]}"; do
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
    log="$work/$name.log"
    echo "fuzz.sh: $name for ${seconds}s (seeds: fuzz/corpus/$corpusName)"
    if "$bin" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
        -artifact_prefix="$artifacts/" -print_final_stats=1 "$corpus" >"$log" 2>&1; then
        runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
        echo "fuzz.sh: $name ok (${runs:-?} inputs)"
    else
        status=1
        echo "fuzz.sh: $name FAILED; end of its log:" >&2
        tail -n 60 "$log" >&2
        mkdir -p "$build/fuzz-artifacts"
        cp "$artifacts"/* "$build/fuzz-artifacts/" 2>/dev/null || true
        echo "fuzz.sh: failing inputs copied to $build/fuzz-artifacts/" >&2
    fi
done
exit $status
