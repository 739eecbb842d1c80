#!/usr/bin/env bash
# tetra's outputs (issue 26): the same tets and the same check at 1, 2 and 3 threads
# (the same .ele bytes at 1, 2 and 3, the serial build's tets without --threads); a 0-based input .node copied (or kept, as the output itself) byte for byte;
# --format npy files that numpy.load reads (skipped without numpy), with the tets of
# the .ele in dtlab's orientation; oracle and bench take --threads.
set -u
. "$(dirname "$0")/expect.sh"

expect 0 "sample" -- "$dtlab" sample builtin --count 3000 --out "$tmp/p.xyz"
for t in 1 2 3; do
  expect 0 "tetra --threads $t --check" -- "$dtlab" tetra "$tmp/p.xyz" --out "$tmp/t$t" --threads "$t" --check
  grep -q "check: valid" "$tmp/out" && pass=$((pass + 1)) || { echo "FAIL: check at $t threads"; fails=$((fails + 1)); }
done
# Without --threads the serial build lists its tets in insertion order; with --threads
# (1 included) the threaded build lists them in the canonical order: the same tet sets
# (vertex sets compared), and byte-identical files at every thread count.
expect 0 "tetra without --threads (serial)" -- "$dtlab" tetra "$tmp/p.xyz" --out "$tmp/s"
same_tets() {
  /usr/bin/python3 - "$1" "$2" <<'PY'
import sys
def tets(path):
    with open(path) as f:
        lines = f.read().split("\n")[1:]
    return sorted(tuple(sorted(map(int, l.split()[1:5]))) for l in lines if l.strip() and not l.startswith("#"))
sys.exit(0 if tets(sys.argv[1]) == tets(sys.argv[2]) else 1)
PY
}
same_tets "$tmp/s.ele" "$tmp/t1.ele" && cmp -s "$tmp/s.node" "$tmp/t1.node" && pass=$((pass + 1)) ||
  { echo "FAIL: tets or points differ between the serial build and --threads 1"; fails=$((fails + 1)); }
for t in 2 3; do
  cmp -s "$tmp/t1.ele" "$tmp/t$t.ele" && cmp -s "$tmp/t1.node" "$tmp/t$t.node" && pass=$((pass + 1)) ||
    { echo "FAIL: .ele or .node bytes differ between 1 and $t threads"; fails=$((fails + 1)); }
done
expect 0 "tetra on a .node (copied)" -- "$dtlab" tetra "$tmp/t1.node" --out "$tmp/c" --json
grep -q '"node_file": "copied"' "$tmp/out" && cmp -s "$tmp/t1.node" "$tmp/c.node" && pass=$((pass + 1)) ||
  { echo "FAIL: the input .node was not copied byte for byte"; fails=$((fails + 1)); }
cp "$tmp/t1.node" "$tmp/k.node"
expect 0 "tetra on a .node into itself (kept)" -- "$dtlab" tetra "$tmp/k.node" --out "$tmp/k" --json
grep -q '"node_file": "kept"' "$tmp/out" && cmp -s "$tmp/t1.node" "$tmp/k.node" && cmp -s "$tmp/s.ele" "$tmp/k.ele" &&
  pass=$((pass + 1)) || { echo "FAIL: the kept .node or its .ele changed"; fails=$((fails + 1)); }
expect 0 "dtlab check on the kept pair" -- "$dtlab" check "$tmp/k"
expect 2 "--format bad" -- "$dtlab" tetra "$tmp/p.xyz" --out "$tmp/x" --format csv
expect 2 "--threads -1" -- "$dtlab" tetra "$tmp/p.xyz" --threads -1
expect 0 "tetra --format npy" -- "$dtlab" tetra "$tmp/p.xyz" --out "$tmp/n" --format npy
if /usr/bin/python3 -c "import numpy" 2>/dev/null; then
  /usr/bin/python3 - "$tmp" <<'PY' && pass=$((pass + 1)) || fails=$((fails + 1))
import sys, numpy as np
d = sys.argv[1]
p, t = np.load(d + "/n.points.npy"), np.load(d + "/n.tets.npy")
assert p.dtype == np.float64 and p.shape == (3000, 3), (p.dtype, p.shape)
ele = np.loadtxt(d + "/s.ele", skiprows=1, dtype=np.int64)[:, 1:]
ele[:, [0, 1]] = ele[:, [1, 0]]  # .ele is TetGen's orientation
assert t.dtype == np.uint32 and (t == ele).all(), "npy tets differ from the .ele"
xyz = np.loadtxt(d + "/p.xyz")
assert (p == xyz).all(), "npy points differ from the input"
PY
else
  echo "SKIP: numpy not installed (python3-numpy): .npy not read back"
fi
# A set is written whole or not at all (the sixth probe): with PREFIX.ele a FIFO nobody
# reads, the .node is in place when the .ele's open fails (after DTLAB_FIFO_WAIT) or the
# run is interrupted there; either way the new .node goes with it, the FIFO stays.
rm -f "$tmp/w.node" "$tmp/w.ele"
mkfifo "$tmp/w.ele"
expect 2 "an .ele that cannot be written" -- env DTLAB_FIFO_WAIT=1 "$dtlab" tetra "$tmp/p.xyz" --out "$tmp/w"
ok "no .node left without its .ele (a failure)" [ ! -e "$tmp/w.node" ]
env DTLAB_FIFO_WAIT=60 "$dtlab" tetra "$tmp/p.xyz" --out "$tmp/w" >/dev/null 2>&1 &
run=$!
for _ in $(seq 200); do [ -e "$tmp/w.node" ] && break; sleep 0.05; done
ok "the .node was in place before the interrupt" [ -e "$tmp/w.node" ]
kill -TERM "$run"
wait "$run"
ok "no .node left without its .ele (SIGTERM)" [ ! -e "$tmp/w.node" ]
ok "the FIFO is left a FIFO" [ -p "$tmp/w.ele" ]
rm -f "$tmp/w.ele"
# Enough points for parallel passes (a pass gives each thread at least 2048): the same
# bytes at 1, 2 and 3 threads; voronoi's cells are computed from the DT, so its files too.
expect 0 "sample 40000" -- "$dtlab" sample builtin --count 40000 --out "$tmp/q.xyz"
for t in 1 2 3; do
  expect 0 "tetra 40000 --threads $t" -- "$dtlab" tetra "$tmp/q.xyz" --out "$tmp/q$t" --threads "$t" --json
done
says "parallel passes ran at 3 threads" '"passes": [1-9]'
for t in 2 3; do
  cmp -s "$tmp/q1.ele" "$tmp/q$t.ele" && pass=$((pass + 1)) ||
    { echo "FAIL: .ele bytes differ between 1 and $t threads at 40000 points"; fails=$((fails + 1)); }
done
for t in 1 2; do
  expect 0 "voronoi --threads $t" -- "$dtlab" voronoi "$tmp/q.xyz" --out "$tmp/v$t" --threads "$t" --quiet
done
cmp -s "$tmp/v1.obj" "$tmp/v2.obj" && pass=$((pass + 1)) ||
  { echo "FAIL: voronoi's .obj differs between 1 and 2 threads"; fails=$((fails + 1)); }
expect 0 "oracle --threads 2" -- "$dtlab" oracle "$tmp/p.xyz" --against cgal --threads 2 --quiet
expect 0 "bench with the parallel peers" -- "$dtlab" bench --sizes 2000 --runs 1 --tools dtlab,cgal-parallel,gmsh-hxt \
  --threads 2 --quiet --json

echo "$pass passed, $fails failed"
[ "$fails" -eq 0 ]
