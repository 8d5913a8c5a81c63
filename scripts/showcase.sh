#!/usr/bin/env bash
# Generates the showcase: every example L-system as .glb, .obj (+.mtl) and a .png preview.
# Usage: scripts/showcase.sh RAMUS_BINARY OUT_DIR
set -euo pipefail
ramus=$1
out=$2
cd "$(dirname "$0")/.."
mkdir -p "$out/lsystems"
count=0
for file in examples/lsystems/*.lsys; do
  name=$(basename "$file" .lsys)
  "$ramus" lsystem "$file" -o "$out/lsystems/$name.glb" --png "$out/lsystems/$name.png" \
    --view front --stats > "$out/lsystems/$name.stats.json"
  "$ramus" lsystem "$file" -o "$out/lsystems/$name.obj"
  count=$((count + 1))
  printf '  %-24s %s\n' "$name" "$(cat "$out/lsystems/$name.stats.json")"
done
echo
echo "showcase: $count L-systems written to $(cd "$out" && pwd)/lsystems (.glb, .obj/.mtl, .png)"
