#!/usr/bin/env python3
"""Unites the welded bark of random bracketed L-systems (`ramus lsystem FILE --union`).

Each seed gives one small random plant (2-4 derivations of random successors for X and F, random
branching angle); the union must end within the time limit and leave one clean surface (no
crossing pairs, pinched edges or touching points left, no failed union), or be refused at once
by its work limit (overlap too dense to cut: counted apart, as are plants that draw nothing).
Prints one line per plant that does not, and a summary; exits 1 if any does not.
`make random-union-check` runs seeds 1-400 (docs/welded.md, Performance, "Session 43" and
"Session 44"). The plants are written to a temporary folder, or to
--keep DIR to look at them afterwards.
"""
import argparse
import json
import pathlib
import random
import subprocess
import sys
import tempfile
import time


def successor(rng, depth=0):
    symbols = []
    for _ in range(rng.randint(2, 7)):
        c = rng.random()
        if c < 0.35:
            symbols.append("F")
        elif c < 0.6:
            symbols.append(rng.choice(["+", "-", "&", "^", "/", "\\", "|"]))
        elif c < 0.8 and depth < 2:
            symbols.append("[" + successor(rng, depth + 1) + "]")
        elif c < 0.9:
            symbols.append("X")
        elif rng.random() < 0.3:
            symbols.append("!(%.2f)" % rng.uniform(0.02, 0.5))
        else:
            symbols.append("f" if rng.random() < 0.2 else "F")
    return "".join(symbols)


def plant(seed):
    rng = random.Random(seed)
    angle = rng.choice([15, 20, 22.5, 25.7, 30, 45, 60, 90, rng.uniform(5, 120)])
    lines = [
        "derivations: %d" % rng.randint(2, 4),
        "angle: %.3f" % angle,
        "axiom: " + rng.choice(["F", "X", "FX", "F[+X]F[-X]"]),
        "X -> " + successor(rng),
        "F -> " + rng.choice(["FF", "F", "F[+F]F", "F" + successor(rng)]),
    ]
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ramus", default="build/release/ramus")
    parser.add_argument("--from", dest="first", type=int, default=1)
    parser.add_argument("--to", dest="last", type=int, default=400)
    parser.add_argument("--timeout", type=float, default=60.0, help="seconds per plant")
    parser.add_argument("--keep", help="folder for the plants and their GLBs")
    args = parser.parse_args()
    folder = pathlib.Path(args.keep or tempfile.mkdtemp(prefix="ramus-random-unions."))
    folder.mkdir(parents=True, exist_ok=True)
    bad = 0
    refused = 0
    empty = 0
    slowest = (0.0, None)
    start = time.monotonic()
    for seed in range(args.first, args.last + 1):
        source = folder / ("plant_%d.lsys" % seed)
        source.write_text(plant(seed))
        command = [args.ramus, "lsystem", str(source), "--union", "--no-textures", "--stats",
                   "-o", str(folder / ("plant_%d.glb" % seed))]
        try:
            run = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout)
        except subprocess.TimeoutExpired:
            print("seed %d: still uniting after %.0f s (%s)" % (seed, args.timeout, source))
            bad += 1
            continue
        if run.returncode != 0:
            print("seed %d: exit %d: %s" % (seed, run.returncode, run.stderr.strip()[-300:]))
            bad += 1
            continue
        stats = json.loads(run.stdout)
        if stats.get("edges", 0) == 0:  # nothing drawn (X -> |&): nothing to unite
            empty += 1
            continue
        if stats.get("unions_failed", 0) and "overlap too densely" in run.stderr:
            # The union's work limit (kSolidUnionSegmentPairsPerTriangle): refused at once,
            # the welded mesh written; not a runaway.
            print("seed %d: refused by the work limit (%s)" % (seed, source))
            refused += 1
            continue
        defects = {k: stats.get(k, 0) for k in ("unions_failed", "union_crossings_left",
                                                  "union_pinched_edges", "union_touching_points")}
        if stats.get("unions_applied", 0) < 1 or any(defects.values()):
            print("seed %d: not one clean surface: %s (%s)" % (seed, defects, source))
            bad += 1
        slowest = max(slowest, (stats.get("mesh_seconds", 0.0), seed))
    count = args.last - args.first + 1
    print("random unions: %d plants (%d with no branch drawn), %d not united cleanly within "
          "%.0f s, %d refused by the work limit; slowest seed %s (%.2f s); %.0f s in all"
          % (count, empty, bad, args.timeout, refused, slowest[1], slowest[0],
             time.monotonic() - start))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
