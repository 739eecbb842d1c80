#!/usr/bin/env bash
# End-to-end checks of the dtlab command as a user runs it: exit codes 0/1/2,
# one-line file:line errors, --help and --json on every subcommand, and a small demo.
set -u
. "$(dirname "$0")/expect.sh"
for sub in tetra check oracle fuzz sample voronoi fracture bench experiment demo mesh "mesh check" "mesh repair"; do
  expect 0 "$sub --help" -- "$dtlab" $sub --help
done
# Every command that does work offers --json.
for sub in tetra check oracle fuzz sample voronoi fracture bench demo "experiment thesis-failures" "experiment benchmark" "mesh check" "mesh repair"; do
  $dtlab $sub --help | grep -q -- "--json" || { echo "FAIL: $sub has no --json"; fails=$((fails + 1)); }
done
expect 2 "no subcommand" -- "$dtlab"
expect 2 "unknown subcommand" -- "$dtlab" frobnicate

printf '5 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 one\n4 1 1 1\n' > "$tmp/bad.node"
expect 2 "malformed .node" -- "$dtlab" tetra "$tmp/bad.node"
if ! grep -qx "dtlab tetra: $tmp/bad.node:5: not a number: 'one'" "$tmp/err"; then
  echo "FAIL: malformed .node message: $(cat "$tmp/err")"; fails=$((fails + 1))
fi
expect 2 "missing file" -- "$dtlab" tetra "$tmp/none.xyz"
printf '0 0 0\n1 0 0\n0 1 0\n1 1 0\n' > "$tmp/flat.xyz"
expect 2 "coplanar input" -- "$dtlab" tetra "$tmp/flat.xyz"

printf '0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n0 0 0\n0.5 0.5 0.5\n' > "$tmp/ok.xyz"
expect 0 "tetra" -- "$dtlab" tetra "$tmp/ok.xyz" --out "$tmp/ok" --vtu --json
grep -q '"duplicates": \[' "$tmp/out" || { echo "FAIL: tetra --json lacks duplicates"; fails=$((fails + 1)); }
grep -q '5' "$tmp/out" || true
expect 0 "check our output" -- "$dtlab" check "$tmp/ok"
# Break one tet: the checker must find a defect (exit 1).
sed -i '2s/.*/0 0 1 2 4/' "$tmp/ok.ele"
expect 1 "check a broken mesh" -- "$dtlab" check "$tmp/ok"
expect 2 "bad boundary option" -- "$dtlab" tetra "$tmp/ok.xyz" --boundary bigtet:x
expect 0 "bigtet boundary" -- "$dtlab" tetra "$tmp/ok.xyz" --boundary bigtet:100 --predicates exact --perturb none --order input
printf 'OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n' > "$tmp/cube.off"
expect 0 "tetra on a mesh file's vertices" -- "$dtlab" tetra "$tmp/cube.off" --out "$tmp/cube"
expect 0 "check the cube" -- "$dtlab" check "$tmp/cube"
expect 0 "mesh check a solid" -- "$dtlab" mesh check "$tmp/cube.off"
printf 'OFF\n8 5 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n' > "$tmp/open.off"
expect 1 "mesh check an open box" -- "$dtlab" mesh check "$tmp/open.off"
grep -q "not closed: 4 boundary edges in 1 boundary loop" "$tmp/out" || { echo "FAIL: mesh check words"; fails=$((fails + 1)); }
expect 0 "counts take the syntax of every number (2e0)" -- "$dtlab" fuzz --family uniform --cases 2e0 --no-shrink --out "$tmp/fz_e"
expect 2 "a count must be whole" -- "$dtlab" fuzz --family uniform --cases 2.5 --out "$tmp/fz_h"
expect 2 "fracture without an output" -- "$dtlab" fracture builtin --pieces 2
grep -q "nothing to write" "$tmp/err" || { echo "FAIL: fracture without --out"; fails=$((fails + 1)); }
expect 2 "fracture refuses an open box" -- "$dtlab" fracture "$tmp/open.off" --pieces 4 --out "$tmp/open_frac"
grep -q "not a solid: not closed: 4 boundary edges" "$tmp/err" || { echo "FAIL: fracture refusal words"; fails=$((fails + 1)); }
expect 0 "mesh repair an open box" -- "$dtlab" mesh repair "$tmp/open.off" --out "$tmp/closed.off"
expect 0 "mesh check the repaired box" -- "$dtlab" mesh check "$tmp/closed.off"
expect 0 "fracture --repair --split" -- "$dtlab" fracture "$tmp/open.off" --repair --split --pieces 4 --out "$tmp/frac"
[ -s "$tmp/frac/pieces/piece_0000.obj" ] || { echo "FAIL: --split wrote no piece file"; fails=$((fails + 1)); }
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' > "$tmp/tri.off"
expect 2 "mesh repair refuses a single triangle" -- "$dtlab" mesh repair "$tmp/tri.off" --out "$tmp/tri_fixed.off"
expect 0 "demo (small)" -- "$dtlab" demo --out "$tmp/demo" --points 2000 --pieces 5 --no-oracles
[ -s "$tmp/demo/fracture/exploded.png" ] || { echo "FAIL: demo wrote no PNG"; fails=$((fails + 1)); }
[ -s "$tmp/demo/voronoi_cells.png" ] || { echo "FAIL: demo drew no Voronoi cells"; fails=$((fails + 1)); }
# Binary VTU (the default) against --vtu-format ascii, decoded by a Python reader.
vtu_same() {
  if /usr/bin/python3 "$(dirname "$0")/vtu_compare.py" "$1" "$2"; then pass=$((pass + 1)); else
    echo "FAIL: $2 differs from $1"; fails=$((fails + 1)); fi
}
expect 0 "tetra --vtu" -- "$dtlab" tetra "$tmp/ok.xyz" --out "$tmp/tb" --vtu
expect 0 "tetra --vtu-format ascii" -- "$dtlab" tetra "$tmp/ok.xyz" --out "$tmp/ta" --vtu --vtu-format ascii
vtu_same "$tmp/ta.vtu" "$tmp/tb.vtu"
expect 0 "voronoi --vtu" -- "$dtlab" voronoi "$tmp/ok.xyz" --out "$tmp/vb" --vtu
expect 0 "voronoi --vtu-format ascii" -- "$dtlab" voronoi "$tmp/ok.xyz" --out "$tmp/va" --vtu --vtu-format ascii
vtu_same "$tmp/va.vtu" "$tmp/vb.vtu"
expect 0 "fracture --vtu" -- "$dtlab" fracture "$tmp/cube.off" --pieces 6 --out "$tmp/fb" --vtu
expect 0 "fracture --vtu-format ascii" -- "$dtlab" fracture "$tmp/cube.off" --pieces 6 --out "$tmp/fa" --vtu --vtu-format ascii
vtu_same "$tmp/fa/pieces.vtu" "$tmp/fb/pieces.vtu"
expect 2 "a bad --vtu-format" -- "$dtlab" voronoi "$tmp/ok.xyz" --out "$tmp/vx" --vtu --vtu-format raw
expect 0 "voronoi --tets --vtu-format ascii" -- "$dtlab" voronoi "$tmp/ok.xyz" --out "$tmp/vt" --tets --vtu-format ascii
[ -s "$tmp/vt.tets.vtu" ] && pass=$((pass + 1)) || { echo "FAIL: no .tets.vtu"; fails=$((fails + 1)); }
# An output option that would write nothing is refused, not ignored (exit 2).
expect 2 "tetra --vtu without --out" -- "$dtlab" tetra "$tmp/ok.xyz" --vtu
expect 2 "tetra --format npy without --out" -- "$dtlab" tetra "$tmp/ok.xyz" --format npy
expect 2 "tetra --vtu-format without --vtu" -- "$dtlab" tetra "$tmp/ok.xyz" --out "$tmp/tx" --vtu-format ascii
expect 2 "voronoi --vtu without --out" -- "$dtlab" voronoi "$tmp/ok.xyz" --vtu
expect 2 "voronoi --tets without --out" -- "$dtlab" voronoi "$tmp/ok.xyz" --tets
expect 2 "voronoi --vtu-format without --vtu or --tets" -- "$dtlab" voronoi "$tmp/ok.xyz" --out "$tmp/vx" --vtu-format ascii
expect 2 "voronoi --png-shrink without --png" -- "$dtlab" voronoi "$tmp/ok.xyz" --png-shrink 0.5
expect 2 "fracture --vtu-format without a .vtu" -- "$dtlab" fracture "$tmp/cube.off" --pieces 6 --out "$tmp/fx" --vtu-format ascii

echo "$pass passed, $fails failed"
[ "$fails" -eq 0 ]
