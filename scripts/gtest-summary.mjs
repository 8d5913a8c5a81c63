// Prints GoogleTest's JSON reports (--gtest_output=json:FILE …) as the plain closing line CI reads:
// "tests: N passed, M failed[, K skipped]". Exits 1 when the report is missing or counts none.
import { readFileSync } from 'node:fs';

// Several reports (one per shard) are added up. `--slowest N` first lists the N slowest tests
// with their seconds, slowest first (what scripts/test-shards.sh's heavy list is made of).
let args = process.argv.slice(2);
let slowest = 0;
if (args[0] === '--slowest') {
  slowest = Number(args[1]);
  if (!Number.isInteger(slowest) || slowest < 1) {
    console.error('gtest-summary: --slowest needs a whole number of tests');
    process.exit(2);
  }
  args = args.slice(2);
}
const files = args;
let passed = 0, failed = 0, skipped = 0;
const times = [];
for (const file of files) {
  let report;
  try {
    report = JSON.parse(readFileSync(file, 'utf8'));
  } catch (e) {
    console.error(`gtest-summary: cannot read ${file}: ${e.message}`);
    process.exit(1);
  }
  for (const suite of report.testsuites ?? []) {
    for (const test of suite.testsuite ?? []) {
      if (test.result === 'SKIPPED' || test.status === 'NOTRUN') skipped++;
      else if ((test.failures ?? []).length > 0) failed++;
      else passed++;
      times.push([parseFloat(test.time), `${suite.name}.${test.name}`]);
    }
  }
}
times.sort((a, b) => b[0] - a[0]);
for (const [seconds, name] of times.slice(0, slowest)) console.log(`${seconds.toFixed(1).padStart(7)} s  ${name}`);
if (passed + failed === 0) {
  console.error('gtest-summary: the report counts no executed test');
  process.exit(1);
}
console.log(`tests: ${passed} passed, ${failed} failed` + (skipped ? `, ${skipped} skipped` : ''));
process.exit(failed > 0 ? 1 : 0);
