// Derivation throughput of the npm package `lindenmayer` (1.5.4) on the systems that
// bench/lsystem_bench.cpp measures for ramus (examples/lsystems/*.lsys), so run.sh can print
// them side by side. Prints one JSON object per line:
//   {"system", "n", "modules", "seconds", "wall_seconds", "modules_per_s", "runs"}
// `seconds` is the median CPU time (user + system of the whole node process, so garbage
// collector and JIT threads count) of one derivation from the axiom over `runs` timed runs,
// after one warm-up run; `wall_seconds` the median wall time; modules the word's length.
// CPU time is what run.sh compares, because the machines we measure on are shared.
//
// Usage: node lindenmayer_bench.mjs [system ...]   (default: all of abop_1_24f abop_2_6a
// abop_1_31a)
import LSystem from 'lindenmayer';

const kMinSeconds = 1.0;  // keep timing until this much wall time has been spent …
const kMinRuns = 3;       // … and at least this many runs,
const kMaxRuns = 15;      // but never more than this many.

// ABOP fig 1.24f (examples/lsystems/abop_1_24f.lsys): plain string rewriting.
function abop124f() {
  return new LSystem({axiom: 'X', productions: {X: 'F-[[X]+X]+F[+FX]-X', F: 'FF'}});
}

// ABOP fig 2.6a (examples/lsystems/abop_2_6a.lsys): parametric modules as objects with a
// `params` array, productions as functions — the library's documented way to write
// parametric L-systems.
function abop26a() {
  const r1 = 0.9, r2 = 0.6, a0 = 45, a2 = 45, d = 137.5, wr = 0.707;
  const m = (symbol, ...params) => ({symbol, params});
  return new LSystem({
    axiom: [m('A', 1, 0.15)],
    productions: {
      A: ({part}) => {
        const [l, w] = part.params;
        return [m('!', w), m('F', l), m('['), m('&', a0), m('B', l * r2, w * wr), m(']'),
                m('/', d), m('A', l * r1, w * wr)];
      },
      B: ({part}) => {
        const [l, w] = part.params;
        return [m('!', w), m('F', l), m('['), m('-', a2), m('$'), m('C', l * r2, w * wr),
                m(']'), m('C', l * r1, w * wr)];
      },
      C: ({part}) => {
        const [l, w] = part.params;
        return [m('!', w), m('F', l), m('['), m('+', a2), m('$'), m('B', l * r2, w * wr),
                m(']'), m('B', l * r1, w * wr)];
      },
    },
  });
}

// ABOP fig 1.31a (examples/lsystems/abop_1_31a.lsys): the library's classic "l<p>r" syntax.
// Note: lindenmayer's right-context search continues past the `]` that closes the module's
// branch (ABOP/cpfg stop there), so its words differ from ABOP's (and ramus') after a few
// steps; run.sh prints both module counts.
function abop131a() {
  return new LSystem({
    axiom: 'F1F1F1',
    ignoredSymbols: '+-F',
    productions: {
      '0<0>0': '0', '0<0>1': '1[+F1F1]', '0<1>0': '1', '0<1>1': '1',
      '1<0>0': '0', '1<0>1': '1F1', '1<1>0': '0', '1<1>1': '0',
      '+': '-', '-': '+',
    },
  });
}

const kSystems = {
  abop_1_24f: {make: abop124f, sizes: [6, 7, 8, 9, 10]},
  abop_2_6a: {make: abop26a, sizes: [10, 11, 12, 13, 14, 15, 16]},
  abop_1_31a: {make: abop131a, sizes: [10, 20, 30]},
};

function deriveOnce(make, n) {
  const system = make();
  const cpuStart = process.cpuUsage();
  const wallStart = process.hrtime.bigint();
  const word = system.iterate(n);
  const wall = Number(process.hrtime.bigint() - wallStart) / 1e9;
  const cpu = process.cpuUsage(cpuStart);
  return {seconds: (cpu.user + cpu.system) / 1e6, wall, modules: word.length};
}

function median(values) {
  const sorted = [...values].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  return sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
}

function measure(name, make, n) {
  const {modules} = deriveOnce(make, n);  // warm-up (JIT), also gives the module count
  const times = [], walls = [];
  let spent = 0;
  while (times.length < kMaxRuns && (times.length < kMinRuns || spent < kMinSeconds)) {
    const run = deriveOnce(make, n);
    if (run.modules !== modules) throw new Error(`${name} n=${n}: word length changed`);
    times.push(run.seconds);
    walls.push(run.wall);
    spent += run.wall;
  }
  const seconds = median(times);
  return {system: name, n, modules, seconds, wall_seconds: median(walls),
          modules_per_s: modules / seconds, runs: times.length};
}

const wanted = process.argv.length > 2 ? process.argv.slice(2) : Object.keys(kSystems);
for (const name of wanted) {
  const entry = kSystems[name];
  if (!entry) {
    console.error(`error: unknown system '${name}'; expected one of ${Object.keys(kSystems)}`);
    process.exit(2);
  }
  for (const n of entry.sizes) console.log(JSON.stringify(measure(name, entry.make, n)));
}
