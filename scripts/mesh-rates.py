#!/usr/bin/env python3
"""Meshing rate of every shipped example in one-shot `ramus` runs (welded triangles per second).

Runs `ramus lsystem|colonize EXAMPLE MODE --no-textures --stats` RUNS times per example and prints
the best `mesh_seconds` (the mesh stage of the CLI: welding, junction shrinking, the union with
--union) and the triangles per second it gives; `make weld-rates` runs it for `--weld`.

The stats go to a file that is read after ramus has ended. Piping them into a parser, as a shell
`ramus ... | python3 -c ...` does, starts the parser beside ramus: on a 2-core machine it takes a
core from the junction threads while it starts up, and --weld on ABOP 1.24a then measured 0.166 s
instead of 0.106 s (docs/BENCHMARKS.md, session 46). Prints one line per example and the slowest;
exits 1 if any example is below --min-rate (M triangles/s, default 0: report only).
"""
import argparse
import json
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent


def examples():
    for path in sorted((ROOT / "examples" / "lsystems").glob("*.lsys")):
        yield "lsystem", path
    for path in sorted((ROOT / "examples" / "colonize").glob("*.json")):
        yield "colonize", path


def best_run(ramus, command, path, mode, runs, folder):
    stats_file = folder / "stats.json"
    best = None
    for _ in range(runs):
        with open(stats_file, "w") as out:
            subprocess.run([ramus, command, str(path), mode, "--no-textures", "--stats",
                            "-o", str(folder / "mesh.glb")],
                           stdout=out, stderr=subprocess.DEVNULL, check=True)
        stats = json.loads(stats_file.read_text())
        if best is None or stats["mesh_seconds"] < best["mesh_seconds"]:
            best = stats
    return best["triangles"], best["mesh_seconds"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--ramus", default=str(ROOT / "build" / "release" / "ramus"))
    parser.add_argument("--mode", default="--weld", help="--weld or --union (written --mode=--union)")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--only", help="examples whose name contains this")
    parser.add_argument("--min-rate", type=float, default=0.0,
                        help="M triangles/s every example must reach")
    args = parser.parse_args()

    slowest = None
    with tempfile.TemporaryDirectory() as tmp:
        folder = pathlib.Path(tmp)
        print(f"{'example':<18}{'triangles':>10}{'mesh s':>10}{'M tri/s':>9}")
        for command, path in examples():
            if args.only and args.only not in path.stem:
                continue
            triangles, seconds = best_run(args.ramus, command, path, args.mode, args.runs, folder)
            rate = triangles / seconds / 1e6
            print(f"{path.stem:<18}{triangles:>10}{seconds:>10.4f}{rate:>9.2f}", flush=True)
            if slowest is None or rate < slowest[1]:
                slowest = (path.stem, rate)
    if slowest is None:
        sys.exit("no example matched")
    print(f"slowest: {slowest[0]} {slowest[1]:.2f} M triangles/s ({args.mode}, best of {args.runs})")
    if slowest[1] < args.min_rate:
        sys.exit(1)


if __name__ == "__main__":
    main()
