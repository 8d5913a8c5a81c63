// Prints GoogleTest's JSON reports (--gtest_output=json:FILE …) as the plain closing line CI reads:
// "tests: N passed, M failed[, K skipped]". Exits 1 when the report is missing or counts none.
import { readFileSync } from 'node:fs';

// Several reports (one per shard) are added up.
const files = process.argv.slice(2);
let passed = 0, failed = 0, skipped = 0;
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
    }
  }
}
if (passed + failed === 0) {
  console.error('gtest-summary: the report counts no executed test');
  process.exit(1);
}
console.log(`tests: ${passed} passed, ${failed} failed` + (skipped ? `, ${skipped} skipped` : ''));
process.exit(failed > 0 ? 1 : 0);
