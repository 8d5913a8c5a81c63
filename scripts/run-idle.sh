#!/usr/bin/env bash
# Runs COMMAND at the lowest CPU priority, for work that should only take cycles others leave idle
# (make test compiles the fuzzers this way beside the tests). Start it under `setsid` so that the
# caller can end the whole process group. Where the kernel groups processes by session for
# scheduling (autogroup), nice only ranks processes within one group and a new session is a new
# group, so that group's own priority is lowered too.
#
# Usage: setsid scripts/run-idle.sh COMMAND [ARG...]
set -euo pipefail
if [[ $# -lt 1 ]]; then
    echo "usage: $0 COMMAND [ARG...]" >&2
    exit 2
fi
if [[ -w /proc/self/autogroup ]]; then
    echo 19 >/proc/self/autogroup 2>/dev/null || true
fi
exec nice -n 19 "$@"
