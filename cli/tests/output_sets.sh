#!/usr/bin/env bash
# A command's outputs are one set (cli/old_outputs.hpp): every old member of PREFIX (tetra,
# voronoi) or DIR (fracture) is removed before the first new file, also the members this
# run does not write (an old .vtu beside a new .node/.ele, piece files of an earlier
# --split run with more pieces), each such removal noted on stderr; the input is kept.
set -u
. "$(dirname "$0")/expect.sh"

expect 0 "sample" -- "$dtlab" sample builtin --count 500 --out "$tmp/p.xyz"
expect 0 "tetra --vtu" -- "$dtlab" tetra "$tmp/p.xyz" --out "$tmp/t" --vtu
ok "tetra wrote .node/.ele/.vtu" test -f "$tmp/t.node" -a -f "$tmp/t.ele" -a -f "$tmp/t.vtu"
expect 0 "tetra without --vtu" -- "$dtlab" tetra "$tmp/p.xyz" --out "$tmp/t"
ok "the old .vtu is gone" test ! -e "$tmp/t.vtu"
says "the removal is noted" "note: removed .*t\.vtu of an earlier run"
expect 0 "tetra --format npy" -- "$dtlab" tetra "$tmp/p.xyz" --out "$tmp/t" --format npy
ok "the text pair is gone beside the .npy pair" test ! -e "$tmp/t.node" -a ! -e "$tmp/t.ele" -a -f "$tmp/t.tets.npy"
says "the removals are noted" "note: removed 2 files of an earlier run"
expect 0 "tetra text again" -- "$dtlab" tetra "$tmp/p.xyz" --out "$tmp/t"
ok "the .npy pair is gone" test ! -e "$tmp/t.points.npy" -a ! -e "$tmp/t.tets.npy" -a -f "$tmp/t.ele"
expect 0 "tetra text a third time" -- "$dtlab" tetra "$tmp/p.xyz" --out "$tmp/t"
never "nothing to note when the set is rewritten" "note: removed"
# The input .node read as PREFIX.node is a member of the npy run's other set: kept.
cp "$tmp/t.node" "$tmp/k.node"
expect 0 "tetra k.node --out k --format npy" -- "$dtlab" tetra "$tmp/k.node" --out "$tmp/k" --format npy
ok "the input .node is kept" cmp -s "$tmp/t.node" "$tmp/k.node"

expect 0 "voronoi --vtu --tets" -- "$dtlab" voronoi "$tmp/p.xyz" --out "$tmp/v" --vtu --tets
ok "voronoi wrote its set" test -f "$tmp/v.obj" -a -f "$tmp/v.json" -a -f "$tmp/v.vtu" -a -f "$tmp/v.tets.vtu"
expect 0 "voronoi without --vtu --tets" -- "$dtlab" voronoi "$tmp/p.xyz" --out "$tmp/v"
ok "the old .vtu and .tets.vtu are gone" test ! -e "$tmp/v.vtu" -a ! -e "$tmp/v.tets.vtu" -a -f "$tmp/v.obj"
says "the removals are noted" "note: removed 2 files of an earlier run"
expect 0 "voronoi --quiet" -- "$dtlab" voronoi "$tmp/p.xyz" --out "$tmp/v" --vtu --quiet
expect 0 "voronoi --quiet without --vtu" -- "$dtlab" voronoi "$tmp/p.xyz" --out "$tmp/v" --quiet
ok "removed under --quiet too" test ! -e "$tmp/v.vtu"
never "--quiet: no note" "note: removed"

expect 0 "fracture --split --vtu, 6 sites (6 or more pieces)" -- "$dtlab" fracture builtin --pieces 6 --out "$tmp/f" --split --vtu --quiet
ok "six piece files" test -f "$tmp/f/pieces/piece_0005.obj" -a -f "$tmp/f/pieces.vtu"
touch "$tmp/f/pieces/notes.txt"  # not a member: stays
expect 0 "fracture --split, 3 pieces" -- "$dtlab" fracture builtin --pieces 3 --out "$tmp/f" --split
ok "piece files 3-5 and pieces.vtu of the earlier run are gone" \
  test ! -e "$tmp/f/pieces/piece_0003.obj" -a ! -e "$tmp/f/pieces/piece_0005.obj" -a ! -e "$tmp/f/pieces.vtu"
ok "the new piece files and a stranger's file stay" \
  test -f "$tmp/f/pieces/piece_0002.obj" -a -f "$tmp/f/pieces/notes.txt" -a -f "$tmp/f/manifest.json"
says "the removals are noted" "note: removed [4-9][0-9]* files of an earlier run"
expect 0 "fracture without --split" -- "$dtlab" fracture builtin --pieces 3 --out "$tmp/f" --quiet
ok "no piece file of the --split run is left" test ! -e "$tmp/f/pieces/piece_0000.obj"
# A mesh inside DIR is the input: never removed, even where it is a member (repaired.off).
expect 0 "fracture --repair" -- "$dtlab" fracture builtin --pieces 3 --out "$tmp/g" --repair --quiet
cp "$tmp/g/repaired.off" "$tmp/r.off"
expect 0 "fracture DIR/repaired.off --out DIR (no --repair)" -- "$dtlab" fracture "$tmp/g/repaired.off" --pieces 3 \
  --out "$tmp/g" --quiet
ok "the input repaired.off is kept" cmp -s "$tmp/r.off" "$tmp/g/repaired.off"

echo "output_sets: $pass passed, $fails failed"
[ "$fails" -eq 0 ]
