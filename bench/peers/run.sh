#!/usr/bin/env bash
# Side-by-side derivation benchmark: ramus (ramus_bench, Google Benchmark) against the npm
# package `lindenmayer` on the same L-systems (ABOP 1.24f, 2.6a, 1.31a), one process after the
# other on this machine, then a table with module counts of both sides and the speedup.
#
# Usage: bench/peers/run.sh BUILD_DIR
#   BUILD_DIR: a Release build configured with -DRAMUS_BUILD_BENCH=ON (and asserts off) in
#   which `cmake --build BUILD_DIR --target ramus_bench` has been run.
# Environment: RAMUS_BENCH_REPETITIONS (default 5) repetitions per ramus case (median used).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
if [[ $# -ne 1 ]]; then
    echo "usage: $0 BUILD_DIR" >&2
    exit 2
fi
bench="$1/ramus_bench"
if [[ ! -x "$bench" ]]; then
    echo "error: $bench not found; configure with -DRAMUS_BUILD_BENCH=ON and build ramus_bench" >&2
    exit 2
fi
if [[ ! -d "$here/node_modules/lindenmayer" ]]; then
    (cd "$here" && npm ci --no-audit --no-fund >&2)
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
echo "ramus_bench ($bench) …" >&2
"$bench" \
    --benchmark_filter='^BM_Derive/(abop_1_24f/([6-9]|10)|abop_2_6a/1[0-6]|abop_1_31a/[123]0)$' \
    --benchmark_repetitions="${RAMUS_BENCH_REPETITIONS:-5}" \
    --benchmark_report_aggregates_only=true \
    --benchmark_format=json >"$tmp/ramus.json"
echo "lindenmayer $(node -p "require('$here/node_modules/lindenmayer/package.json').version") …" >&2
node "$here/lindenmayer_bench.mjs" >"$tmp/lindenmayer.jsonl"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)" >&2

node --input-type=module - "$tmp/ramus.json" "$tmp/lindenmayer.jsonl" <<'EOF'
import {readFileSync} from 'node:fs';

const [ramusFile, peerFile] = process.argv.slice(2);
const unitSeconds = {ns: 1e-9, us: 1e-6, ms: 1e-3, s: 1};
const ramus = new Map();
// Google Benchmark writes NaN / inf for some aggregates of rate counters: not JSON.
const ramusText = readFileSync(ramusFile, 'utf8').replace(/\b(-?inf|NaN)\b/g, 'null');
for (const b of JSON.parse(ramusText).benchmarks) {
  if (b.aggregate_name !== 'median') continue;
  const [, system, n] = b.run_name.split('/');
  const seconds = b.cpu_time * unitSeconds[b.time_unit];
  const wall = b.real_time * unitSeconds[b.time_unit];
  ramus.set(`${system}/${n}`, {modules: b.modules, seconds, wall});
}
const peer = new Map();
for (const line of readFileSync(peerFile, 'utf8').split('\n')) {
  if (!line.trim()) continue;
  const r = JSON.parse(line);
  peer.set(`${r.system}/${r.n}`, r);
}

const fmt = (x, digits = 1) => x.toFixed(digits);
const rows = [['system', 'n', 'modules ramus', 'modules lindenmayer', 'same',
               'ramus Mmod/s', 'lindenmayer Mmod/s', 'speedup', 'ramus ns/module',
               'ramus wall ms', 'lindenmayer wall ms']];
for (const [key, r] of ramus) {
  const p = peer.get(key);
  const [system, n] = key.split('/');
  const ours = r.modules / r.seconds;
  rows.push([system, n, String(r.modules), p ? String(p.modules) : '-',
             p ? (p.modules === r.modules ? 'yes' : 'NO') : '-', fmt(ours / 1e6, 2),
             p ? fmt(p.modules_per_s / 1e6, 3) : '-',
             p ? fmt(ours / p.modules_per_s) + '×' : '-', fmt(1e9 * r.seconds / r.modules, 2),
             fmt(1e3 * r.wall, 3), p ? fmt(1e3 * p.wall_seconds, 3) : '-']);
}
const widths = rows[0].map((_, c) => Math.max(...rows.map((row) => row[c].length)));
for (const [i, row] of rows.entries()) {
  console.log('| ' + row.map((cell, c) => cell.padStart(widths[c])).join(' | ') + ' |');
  if (i === 0) console.log('|' + widths.map((w) => '-'.repeat(w + 1) + ':').join('|') + '|');
}
console.log('\nCPU time per derivation (median); speedup = (ramus modules/s) / (lindenmayer');
console.log('modules/s), each on its own word;');
console.log('"same = NO" rows compare throughput on words of different length (see README.md).');
EOF
