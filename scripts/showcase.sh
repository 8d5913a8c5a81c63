#!/usr/bin/env bash
# Generates the showcase: every example L-system and colonization config, and the thesis's
# skeleton showcase cases, as .glb, .obj (+.mtl) and .png previews.
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

mkdir -p "$out/colonize"
for file in examples/colonize/*.json; do
  name=$(basename "$file" .json)
  "$ramus" colonize "$file" -o "$out/colonize/$name.glb" --png "$out/colonize/$name.png" \
    --stats > "$out/colonize/$name.stats.json"
  printf '  %-24s %s\n' "$name" "$(cat "$out/colonize/$name.stats.json")"
done
echo "showcase: colonization examples written to $(cd "$out" && pwd)/colonize"

# Production tree assets (issue 9): leaves, wind data, textures and three LODs in one GLB.
as="$out/assets"
mkdir -p "$as"
"$ramus" lsystem examples/lsystems/tree_3d.lsys --leaves --wind --lods 1,0.4,0.15 \
  -o "$as/tree_3d_leaves.glb" --png "$as/tree_3d_leaves.png" --stats > "$as/tree_3d_leaves.stats.json"
"$ramus" colonize examples/colonize/broadleaf.json --leaves --leaves-per-length 0.05 --wind \
  --lods 1,0.4,0.15 -o "$as/broadleaf_leaves.glb" --png "$as/broadleaf_leaves.png" \
  --stats > "$as/broadleaf_leaves.stats.json"
"$ramus" colonize examples/colonize/roots.json --view side -o "$as/roots.glb" \
  --png "$as/roots.png" --stats > "$as/roots.stats.json"
for f in "$as"/*.stats.json; do printf '  %-24s %s\n' "$(basename "$f" .stats.json)" "$(cat "$f")"; done
echo "showcase: tree assets (leaves, wind, LODs) written to $(cd "$out" && pwd)/assets"

# The skeleton cases of seed 000 (figs 5.2, 5.4–5.6, 6.2) and a random set.
sk="$out/skeletons"
mkdir -p "$sk"
skeleton() { "$ramus" skeleton --png --view side -o "$sk" "$@"; }
skeleton --name bird --legs 2 --wings 2 --seed 1
skeleton --name kangaroo --example Kangaroo --legs 2 --arms 2 --seed 1
skeleton --name elephant --example "African elephant" --seed 1
skeleton --name pegasus --legs 4 --wings 2 --two-per-girdle --seed 1
skeleton --name centaur --legs 4 --arms 2 --neck-shoulder forced --seed 1
skeleton --name eight_legs --legs 8 --two-per-girdle --neck-shoulder forbidden --seed 1
skeleton --name fish --legs 0 --wings 0 --fins 4 --two-per-girdle --seed 1
skeleton --name random --count 12 --seed 7
skeleton --name elephant_variation --example "African elephant" --variations --count 4 --seed 3
echo "showcase: skeletons written to $(cd "$sk" && pwd) (NAME<i>.glb/.obj/.json/.png)"

# The same cases with bone models (docs/bones.md), and example species side by side at every
# resolution, tiled into contact sheets.
bones="$out/bones"
mkdir -p "$bones"
for res in low high; do
  b() { "$ramus" skeleton --png --view side --resolution "$res" -o "$bones/$res" "$@"; }
  b --name bird --legs 2 --wings 2 --head bird --seed 1
  b --name kangaroo --example Kangaroo --legs 2 --arms 2 --seed 1
  b --name elephant --example "African elephant" --seed 1
  b --name pegasus --legs 4 --wings 2 --two-per-girdle --seed 1
  b --name centaur --legs 4 --arms 2 --neck-shoulder forced --seed 1
  b --name eight_legs --legs 8 --two-per-girdle --neck-shoulder forbidden --seed 1
  b --name fish --legs 0 --wings 0 --fins 4 --two-per-girdle --head reptile --seed 1
done
sheet=()
# No --head: each example gets the skull of its class (elephant, horse: herbivore; pigeon: bird;
# frog, snake: reptile).
for species in "African elephant" "Horse (warmblood)" "Pigeon" "Frog" "Snake"; do
  stem=$(echo "$species" | tr 'A-Z ' 'a-z_' | tr -cd 'a-z_')
  for res in box low high; do
    "$ramus" skeleton --example "$species" --resolution "$res" --seed 1 \
      --name "${stem}_${res}" -o "$bones/species" >/dev/null
    sheet+=("$bones/species/${stem}_${res}0.glb")
  done
done
"$ramus" render "${sheet[@]}" --sheet --columns 3 --size 400x300 --view side \
  -o "$bones/species_box_low_high.png"
# The default library as a user library (a template to edit; ramus skeleton --bones DIR).
"$ramus" bones export "$bones/library" >/dev/null
echo "showcase: bone models written to $(cd "$bones" && pwd) (low/, high/, species/, species_box_low_high.png, library/)"
