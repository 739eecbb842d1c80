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
# Each piece file is guarded as it is placed: a write that fails on piece 2 (a FIFO no
# process reads), or SIGTERM while it waits there, leaves no piece file of this run (they
# were guarded only after the last one, those new to DIR never); the FIFO stays a FIFO.
only_fifo() { [ -p "$1/pieces/piece_0002.obj" ] && [ "$(ls "$1/pieces")" = "piece_0002.obj" ] && [ ! -e "$1/pieces.obj" ]; }
mkdir -p "$tmp/fw/pieces" && mkfifo "$tmp/fw/pieces/piece_0002.obj"
expect 2 "fracture --split, piece 2 cannot be written" -- env DTLAB_FIFO_WAIT=1 "$dtlab" fracture builtin --pieces 4 \
  --out "$tmp/fw" --split --quiet
says "named" "piece_0002.obj:0: no process opened the FIFO for reading"
ok "no piece file of the failed run is left (a failure)" only_fifo "$tmp/fw"
env DTLAB_FIFO_WAIT=60 "$dtlab" fracture builtin --pieces 4 --out "$tmp/fw" --split --quiet >/dev/null 2>&1 &
run=$!
for _ in $(seq 400); do [ -e "$tmp/fw/pieces/piece_0001.obj" ] && break; sleep 0.05; done
ok "pieces 0 and 1 were in place before the interrupt" test -f "$tmp/fw/pieces/piece_0000.obj" -a \
  -f "$tmp/fw/pieces/piece_0001.obj"
kill -TERM "$run"
wait "$run"
ok "no piece file of the interrupted run is left (SIGTERM)" only_fifo "$tmp/fw"
rm -f "$tmp/fw/pieces/piece_0002.obj"
# A mesh inside DIR is the input: never removed, even where it is a member (repaired.off).
expect 0 "fracture --repair" -- "$dtlab" fracture builtin --pieces 3 --out "$tmp/g" --repair --quiet
cp "$tmp/g/repaired.off" "$tmp/r.off"
expect 0 "fracture DIR/repaired.off --out DIR (no --repair)" -- "$dtlab" fracture "$tmp/g/repaired.off" --pieces 3 \
  --out "$tmp/g" --quiet
ok "the input repaired.off is kept" cmp -s "$tmp/r.off" "$tmp/g/repaired.off"

# No output may replace an input (exit 2 before anything is computed), nor two outputs be one file.
head -300 "$tmp/p.xyz" | sed 's/^/v /' >"$tmp/S.obj"; echo "f 1 2 3" >>"$tmp/S.obj"; cp "$tmp/S.obj" "$tmp/S0.obj"
expect 2 "voronoi S.obj --out S" -- "$dtlab" voronoi "$tmp/S.obj" --out "$tmp/S"
says "named" "S.obj:0: is the input file"
ok "S.obj untouched" cmp -s "$tmp/S.obj" "$tmp/S0.obj"
cp "$tmp/p.xyz" "$tmp/p0.xyz"
expect 2 "voronoi --png onto the input" -- "$dtlab" voronoi "$tmp/p.xyz" --png "$tmp/p.xyz"
ok "the input untouched" cmp -s "$tmp/p.xyz" "$tmp/p0.xyz"
expect 2 "voronoi --png onto the set's .json" -- "$dtlab" voronoi "$tmp/p.xyz" --out "$tmp/w" --png "$tmp/w.json"
says "named" "w.json:0: written twice"
/usr/bin/python3 -c "
import random
random.seed(1)
print('50 3 2 1')
for i in range(50): print(i + 1, random.random(), random.random(), random.random(), 7.5, 8.5, 1)
" >"$tmp/A.node"
cp "$tmp/A.node" "$tmp/A0.node"
expect 2 "tetra A.node --out A (1-based, with attributes: not the output's .node)" -- "$dtlab" tetra "$tmp/A.node" --out "$tmp/A"
ok "A.node untouched" cmp -s "$tmp/A.node" "$tmp/A0.node"
mkdir "$tmp/folder"
expect 2 "tetra --out FOLDER" -- "$dtlab" tetra "$tmp/p.xyz" --out "$tmp/folder"
expect 2 "tetra --out PREFIX/" -- "$dtlab" tetra "$tmp/p.xyz" --out "$tmp/x/"
expect 2 "voronoi --out ''" -- "$dtlab" voronoi "$tmp/p.xyz" --out ""
touch "$tmp/afile"
expect 2 "fracture --out FILE" -- "$dtlab" fracture builtin --pieces 3 --out "$tmp/afile"
says "named" "afile:0: --out: exists and is not a folder"
expect 0 "fracture 1 piece" -- "$dtlab" fracture builtin --pieces 1 --out "$tmp/h" --quiet
cp "$tmp/h/pieces.obj" "$tmp/h0.obj"
expect 2 "fracture DIR/pieces.obj --out DIR" -- "$dtlab" fracture "$tmp/h/pieces.obj" --pieces 3 --out "$tmp/h"
ok "the input mesh untouched" cmp -s "$tmp/h/pieces.obj" "$tmp/h0.obj"
expect 0 "fracture --split" -- "$dtlab" fracture builtin --pieces 4 --out "$tmp/k" --split --quiet
touch "$tmp/k/pieces/piece_12.obj"  # not a name dtlab writes: stays
expect 0 "fracture --sites DIR/pieces/piece_0002.obj --out DIR (no --split)" -- "$dtlab" fracture builtin \
  --sites "$tmp/k/pieces/piece_0002.obj" --out "$tmp/k" --quiet
ok "the sites file is kept, the other piece files go" \
  test -f "$tmp/k/pieces/piece_0002.obj" -a ! -e "$tmp/k/pieces/piece_0001.obj" -a -f "$tmp/k/pieces/piece_12.obj"
expect 2 "fracture --sites DIR/pieces/piece_0002.obj --out DIR --split" -- "$dtlab" fracture builtin \
  --sites "$tmp/k/pieces/piece_0002.obj" --out "$tmp/k" --split --quiet
printf 'OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n' >"$tmp/cube.off"
expect 1 "fracture with a gap that leaves no piece" -- "$dtlab" fracture "$tmp/cube.off" --gap 1 --out "$tmp/gq" --quiet
says "named" "no piece is left"
ok "nothing written" test ! -e "$tmp/gq/manifest.json"

# Every site is accounted for: a repeated site and one whose cell misses the mesh are counted.
printf '0.5 0.5 0.5\n0.5 0.5 0.5\n0.2 0.2 0.2\n5 5 5\n' >"$tmp/s.xyz"
expect 0 "fracture --sites with a repeat and an outsider" -- "$dtlab" fracture "$tmp/cube.off" --sites "$tmp/s.xyz" --out "$tmp/sq"
says "counted" "sites: 4, of which 1 repeat an earlier site .* and 1 have cells that miss the mesh"
ok "the manifest counts them" /usr/bin/python3 -c "import json, sys; m = json.load(open('$tmp/sq/manifest.json')); \
sys.exit(m['sites'] != {'count': 4, 'duplicates': 1, 'without_piece': 1} or len(m['pieces']) != 2)"

echo "output_sets: $pass passed, $fails failed"
[ "$fails" -eq 0 ]
