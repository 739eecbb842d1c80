#!/usr/bin/env bash
# The second hostile probe's finds (tests/finds2/README.txt), replayed: interrupts that
# left peers and temp folders behind, readers that dropped data, campaign files that
# resumed the wrong results, numbers at the edges. Each check asserts the fixed
# behaviour. Usage: finds2_cli.sh DTLAB FINDS2_DIR [PYTHONPATH of the dtlab module]
set -u
finds="$2"
pypath="${3:-}"
py=/usr/bin/python3  # Debian's, with numpy (a pyenv shim may have none)
[ -x "$py" ] || py=python3
EXPECT_TIMEOUT=60
source "$(dirname "$0")/../cli/tests/expect.sh" "$1"

# --- Interrupts: SIGINT to the group, SIGTERM, SIGHUP, SIGKILL during `oracle` with a
# peer that never answers. Afterwards no stand-in runs and the temp folder is empty.
mark="7$$"  # the stand-in's sleep, unique to this run
printf '#!/bin/sh\nsleep 5%s\n' "$mark" > "$tmp/slowtg.sh"
chmod +x "$tmp/slowtg.sh"
running() { ps -eo stat,args | grep -v '^Z' | grep -q "[s]leep 5$mark"; }
interrupt() {  # interrupt SIGNAL WANT_EXIT: starts oracle in its own session, signals its group
  local sig=$1 want=$2 td="$tmp/t-$1"
  mkdir -p "$td"
  TMPDIR="$td" "$py" "$finds/launch.py" "$tmp/int.out" "$dtlab" oracle "$finds/five.xyz" --against tetgen \
    --tetgen "$tmp/slowtg.sh" --quiet &
  local launcher=$!
  for _ in $(seq 50); do running && break; sleep 0.1; done
  ok "$sig: the stand-in peer started" running
  if [ "$sig" = KILL ]; then kill -KILL "$launcher"; else kill -"$sig" -- -"$launcher"; fi
  wait "$launcher"
  local got=$?
  ok "$sig: exit $got, expected $want" [ "$got" -eq "$want" ]
  for _ in $(seq 30); do running || break; sleep 0.1; done
  ok "$sig: no peer left running" bash -c "! { ps -eo stat,args | grep -v '^Z' | grep -q '[s]leep 5$mark'; }"
  for _ in $(seq 30); do [ -z "$(ls -A "$td")" ] && break; sleep 0.1; done
  ok "$sig: the temp folder holds nothing of dtlab's ($(ls "$td"))" [ -z "$(ls -A "$td")" ]
}
interrupt INT 130
interrupt TERM 143
interrupt HUP 129
interrupt KILL 137

# bench forks a measuring child that runs TetGen: SIGINT through `timeout` ends both.
mkdir -p "$tmp/tb"
TMPDIR="$tmp/tb" "$py" "$finds/launch.py" "$tmp/bench.out" timeout -s INT 3 "$dtlab" bench --sizes 2e6 --tools tetgen --runs 1 --quiet
for _ in $(seq 30); do [ -z "$(ls -A "$tmp/tb")" ] && break; sleep 0.1; done
ok "bench + SIGINT: the temp folder holds nothing of dtlab's ($(ls "$tmp/tb"))" [ -z "$(ls -A "$tmp/tb")" ]
ok "bench + SIGINT: no tetgen left" bash -c "! { ps -eo stat,args | grep -v '^Z' | grep -q '[t]etgen -QzJNF $tmp/tb/'; }"

# Python's oracle() answers Ctrl-C within a second, measured from the signal: while a
# peer runs (not after its timeout), and while dtlab's own build and exact check of
# 300000 points run (stages that cannot stop midway: oracle() does not wait for them).
if [ -n "$pypath" ] && PYTHONPATH="$pypath" "$py" -c "import dtlab" 2>/dev/null; then
  cat > "$tmp/py_int.py" <<EOF
import sys, numpy as np
import dtlab
from sigint_self import interrupted_within
n, when, against = int(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
pts = np.random.default_rng(1).random((n, 3))
sys.exit(interrupted_within(when, 1.0, lambda: dtlab.oracle(pts, against=(against,), tetgen="$tmp/slowtg.sh", timeout=30)))
EOF
  expect 0 "python oracle() + SIGINT during a peer answers within a second" -- \
    env PYTHONPATH="$pypath:$(dirname "$0")" "$py" "$tmp/py_int.py" 20 1.5 tetgen
  says "python oracle() raised KeyboardInterrupt" "interrupted 0\.[0-9]+ s after the signal"
  for _ in $(seq 30); do running || break; sleep 0.1; done
  ok "python: no peer left running" bash -c "! { ps -eo stat,args | grep -v '^Z' | grep -q '[s]leep 5$mark'; }"
  for when in 0.3 1.5; do
    expect 0 "python oracle() + SIGINT at $when s into the build and check of 300000 points" -- \
      env PYTHONPATH="$pypath:$(dirname "$0")" "$py" "$tmp/py_int.py" 300000 "$when" tetgen
    says "python oracle() raised KeyboardInterrupt at $when s" "interrupted 0\.[0-9]+ s after the signal"
  done
  ok "python: no peer left after an interrupted build" bash -c "! { ps -eo stat,args | grep -v '^Z' | grep -q '[s]leep 5$mark'; }"
  expect 0 "python check() names a uint64 index as given" -- env PYTHONPATH="$pypath" "$py" -c "
import numpy as np, dtlab
try:
    dtlab.check(np.random.default_rng(1).random((5, 3)), np.array([[0, 1, 2, 2**64 - 1]], dtype=np.uint64))
except ValueError as e:
    assert '18446744073709551615' in str(e), e
else:
    raise SystemExit('accepted')"
else
  echo "finds2_cli: the Python checks skipped (no dtlab module with numpy)"
fi

# --- Readers.
# The fast .ele reader declines a FIFO's content: the strict reader must not reopen it.
printf '5 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 1 1 1\n' > "$tmp/f.node"
mkfifo "$tmp/f.ele"
(printf '# tets\n2 4 0\n0 1 4 2 3\n1 1 3 2 0\n' > "$tmp/f.ele" &)
expect 0 "check with a FIFO .ele does not hang" -- timeout 10 "$dtlab" check "$tmp/f"
# An output FIFO nobody reads: opening it would block for ever; dtlab waits for a reader
# (DTLAB_FIFO_WAIT seconds) and then refuses it. With a reader, the FIFO gets the text.
mkfifo "$tmp/fo.node"
expect 2 "an output FIFO without a reader does not hang" -- env DTLAB_FIFO_WAIT=1 timeout 20 "$dtlab" tetra "$tmp/f.node" --out "$tmp/fo"
says "the FIFO's refusal names it" "fo.node:0: no process opened the FIFO for reading within 1 s"
ok "the FIFO is left a FIFO" [ -p "$tmp/fo.node" ]
(sleep 0.5; cat "$tmp/fo.node" > "$tmp/fo.read") &
reader=$!
expect 0 "an output FIFO whose reader comes late" -- env DTLAB_FIFO_WAIT=10 timeout 20 "$dtlab" tetra "$tmp/f.node" --out "$tmp/fo"
wait "$reader"
ok "the late reader got the .node" grep -q "^5 3 0 0" "$tmp/fo.read"
# Input FIFOs: one nobody writes is refused after DTLAB_FIFO_WAIT seconds (its open
# blocked for ever); a .node FIFO with --out is read once (tetra reopened it to copy the
# input .node, and blocked); a writer that wrote and closed before dtlab opened its own
# end still counts (its data is in the pipe); a mesh FIFO goes through the mesh readers.
# feed SRC FIFO [DELAY]: a writer that gives up after 30 s and holds none of our output.
feed() { timeout 30 sh -c 'sleep "${3:-0}"; cat "$1" > "$2"' _ "$1" "$2" "${3:-0}" >/dev/null 2>&1 & }
mkfifo "$tmp/fi.xyz"
expect 2 "an input FIFO without a writer does not hang" -- env DTLAB_FIFO_WAIT=1 timeout 20 "$dtlab" tetra "$tmp/fi.xyz"
says "the input FIFO's refusal names it" "fi.xyz:0: no process opened the FIFO for writing within 1 s"
mkfifo "$tmp/fi.node"
feed "$tmp/f.node" "$tmp/fi.node"
expect 0 "a .node FIFO with --out is read once" -- timeout 20 "$dtlab" tetra "$tmp/fi.node" --out "$tmp/fi_out"
ok "... and its .node written" grep -q "^5 3 0 0" "$tmp/fi_out.node"
feed "$tmp/f.node" "$tmp/fi.node" 0.5
expect 0 "an input FIFO whose writer comes late" -- env DTLAB_FIFO_WAIT=10 timeout 20 "$dtlab" tetra "$tmp/fi.node" --json
says "the late writer's five points" '"points": 5'
# A writer that holds the FIFO open but writes only after the wait: a slow producer,
# not a missing one (told apart by tee(2), kernel/fifo_wait.hpp).
timeout 30 sh -c 'exec 3>"$1"; sleep 2; cat "$2" >&3' _ "$tmp/fi.node" "$tmp/f.node" >/dev/null 2>&1 &
expect 0 "a connected writer silent past DTLAB_FIFO_WAIT is still read" -- env DTLAB_FIFO_WAIT=1 timeout 20 "$dtlab" tetra "$tmp/fi.node" --json
says "the slow writer's five points" '"points": 5'
printf 'OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' > "$tmp/tet.off"
mkfifo "$tmp/fi.off"
feed "$tmp/tet.off" "$tmp/fi.off"
expect 0 "a mesh FIFO" -- timeout 30 "$dtlab" mesh check "$tmp/fi.off"
# A line too long for the memory is a read error, not the end of the file.
# (Not under the sanitizers, set by CMake: ASan cannot start under ulimit -v.)
if [ -z "${DTLAB_SANITIZE:-}" ]; then
  mkfifo "$tmp/long.xyz"
  ("$py" "$finds/gen_longline.py" > "$tmp/long.xyz" 2>/dev/null &)
  expect 2 "a huge line under ulimit -v" -- bash -c "ulimit -v 400000; exec '$dtlab' tetra '$tmp/long.xyz'"
  says "the huge line is a read error" "long.xyz:1001: read error"
fi
# .xyz: x y z, then numeric attributes, as many on every line.
expect 2 "six.xyz (6 then 3 columns)" -- "$dtlab" tetra "$finds/six.xyz"
says "six.xyz names the column count" "six.xyz:2: expected 6 fields as on line 1, got 3"
expect 2 "junk.xyz" -- "$dtlab" tetra "$finds/junk.xyz"
says "junk.xyz names the line" "junk.xyz:[0-9]+: "
printf '0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n0 0 1 0 0 1\n1 1 1 0 0 1\n' > "$tmp/kitten.xyz"
expect 0 "six columns (x y z nx ny nz) are five points" -- "$dtlab" tetra "$tmp/kitten.xyz" --json
says "kitten.xyz: five points" '"points": 5'
cp "$tmp/kitten.xyz" "$tmp/kitten.pwn"
expect 0 ".pwn is read as .xyz" -- "$dtlab" tetra "$tmp/kitten.pwn"
cp "$tmp/kitten.xyz" "$tmp/UPPER.XYZ"
expect 0 "upper-case .XYZ" -- "$dtlab" tetra "$tmp/UPPER.XYZ"
printf '0 0 0 0 0 1\n1 0 0 0 0 x\n' > "$tmp/junkattr.xyz"
expect 2 "a junk attribute" -- "$dtlab" tetra "$tmp/junkattr.xyz"
says "junk attribute named" "junkattr.xyz:2: not a number: 'x'"
expect 2 "euro.xyz (decimal comma)" -- "$dtlab" tetra "$finds/euro.xyz" --out "$tmp/e"
says "euro.xyz names the decimal comma" "euro.xyz:1: .*decimal comma"
expect 2 "euro.obj (decimal comma)" -- "$dtlab" tetra "$finds/euro.obj"
says "euro.obj names the decimal comma" "euro.obj:1: .*decimal comma"
expect 0 "bom.xyz: a UTF-8 BOM is skipped" -- "$dtlab" tetra "$finds/bom.xyz"
printf '\xef\xbb\xbfx 0 0\n' > "$tmp/bomjunk.xyz"
expect 2 "a junk token after a BOM" -- "$dtlab" tetra "$tmp/bomjunk.xyz"
printf 'x\x01 0 0\n' > "$tmp/ctrl.xyz"
expect 2 "a control character" -- "$dtlab" tetra "$tmp/ctrl.xyz"
says "invisible bytes are shown" "not a number: 'x\\\\x01'"
expect 2 "dim2.node" -- "$dtlab" tetra "$finds/dim2.node"
says "dim2.node names the dimension" "dim2.node:1: dimension must be 3, got 2"
# Meshes: records past the header's count, short counts, float indices, several solids.
for f in off_trailing_faces.off off_header_fewer_faces.off; do
  expect 2 "$f" -- "$dtlab" mesh check "$finds/$f"
  says "$f: data after the last face" "$f:[0-9]+: unexpected data after the last face"
done
expect 2 "ply_ascii_trailing_faces.ply" -- "$dtlab" mesh check "$finds/ply_ascii_trailing_faces.ply"
says "PLY trailing data" "unexpected data after the last element"
expect 2 "ply_float_index_truncated.ply" -- "$dtlab" mesh check "$finds/ply_float_index_truncated.ply"
says "PLY float index" "face index is not an integer"
expect 0 "stl_two_solids.stl: both solids" -- "$dtlab" mesh check "$finds/stl_two_solids.stl"
says "stl_two_solids.stl: 8 triangles" "8 triangles"
expect 2 "nannorm.stl (ASCII NaN normal)" -- "$dtlab" mesh check "$finds/nannorm.stl"
expect 2 "nanbin.stl (binary NaN normal)" -- "$dtlab" mesh check "$finds/nanbin.stl"
says "nanbin.stl names the normal" "non-finite normal"
expect 2 "badcnt.stl (binary with 'solid', wrong count)" -- "$dtlab" mesh check "$finds/badcnt.stl"
says "badcnt.stl: the count, not endsolid" "binary STL announces 5 triangles"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 2 3 9\n' > "$tmp/idx.obj"
expect 2 "OBJ index 9 of 4" -- "$dtlab" mesh check "$tmp/idx.obj"
says "the OBJ index leads, as written" "idx.obj:5: vertex index 9 out of range: 4 vertices so far"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 2 3 -5\n' > "$tmp/neg.obj"
expect 2 "OBJ index -5 of 4" -- "$dtlab" mesh check "$tmp/neg.obj"
says "a negative OBJ index as written" "neg.obj:5: vertex index -5 out of range: 4 vertices so far"
# A line of 999 numbers is refused, not one point (the 100 MB line of the probe).
"$py" -c "print(' '.join(['1'] * 999))" > "$tmp/wide.xyz"
expect 2 "an .xyz line of 999 fields" -- "$dtlab" tetra "$tmp/wide.xyz"
says "wide.xyz: the field cap named" "wide.xyz:1: more than 256 fields on one line"
# Binary PLY: bytes after the last element are refused (a whole extra face here).
"$py" - "$tmp" <<'PY'
import struct, sys
h = (b"ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
     b"property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n")
body = b"".join(struct.pack("<3f", *p) for p in [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)])
body += b"".join(struct.pack("<B3i", 3, *t) for t in [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)])
open(sys.argv[1] + "/bin_ok.ply", "wb").write(h + body)
open(sys.argv[1] + "/bin_trailing.ply", "wb").write(h + body + struct.pack("<B3i", 3, 0, 1, 2))
PY
expect 0 "binary PLY tet" -- "$dtlab" mesh check "$tmp/bin_ok.ply"
expect 2 "binary PLY with a face past the count" -- "$dtlab" mesh check "$tmp/bin_trailing.ply"
says "binary PLY trailing bytes named" "bin_trailing.ply:0: 13 bytes after the last element"
# PLY: a defect of an element's properties names the line of its `element` keyword.
printf 'ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n0\n' > "$tmp/nox.ply"
expect 2 "PLY vertex element without y, z" -- "$dtlab" mesh check "$tmp/nox.ply"
says "PLY: the element's line" "nox.ply:3: vertex element lacks x, y or z property"
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty float q\nend_header\n0 0 0\n1 0 0\n0 1 0\n7\n' > "$tmp/nolist.ply"
expect 2 "PLY face element without an index list" -- "$dtlab" mesh check "$tmp/nolist.ply"
says "PLY: the face element's line" "nolist.ply:7: face element has no vertex index list"
printf 'v 0 0 0 1\nv 1 0 0 0.5 0.5 0.5\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n' > "$tmp/w.obj"
expect 0 "OBJ v x y z [w] and colours" -- "$dtlab" tetra "$tmp/w.obj"

# --- Numbers at the edges: exact cells or exit 2 naming the range.
for f in sc_1e155.xyz sc_1e-300.xyz ulp.xyz mix.xyz; do
  expect 2 "voronoi $f" -- "$dtlab" voronoi "$finds/$f" --out "$tmp/v"
  never "voronoi $f writes no NaN" "nan"
done
# shellcheck disable=SC2046
expect 2 "voronoi --box 1e200" -- "$dtlab" voronoi "$finds/five.xyz" --box $(cat "$finds/voronoi_box_1e200.args") --out "$tmp/v"
says "--box names the range" "--box: '-1e200' is not in \\[-1e\\+101, 1e\\+101\\]"
# shellcheck disable=SC2046
expect 2 "voronoi --check --box 1e200: refused too, not a list of broken cells" -- "$dtlab" voronoi "$finds/five.xyz" --box $(cat "$finds/voronoi_box_1e200.args") --check
says "--check --box names the range" "not in \\[-1e\\+101, 1e\\+101\\]"
expect 0 "voronoi --check --box at the range's end: cells without defects" -- "$dtlab" voronoi "$finds/five.xyz" --box -1e101 -1e101 -1e101 1e101 1e101 1e101 --check
says "--box 1e101: no defect" "check: 0 defect\\(s\\)"
printf '1e100 0 0\n-1e100 0 0\n0 1e100 0\n0 0 1e100\n0 0 -1e100\n' > "$tmp/e100.xyz"
expect 0 "voronoi --check, sites at 1e100 with the default box" -- "$dtlab" voronoi "$tmp/e100.xyz" --check
for c in "" --check; do
  expect 2 "voronoi $c, --margin 1e6 grows the box of sites at 1e100 out of range" -- "$dtlab" voronoi "$tmp/e100.xyz" --margin 1e6 $c
  says "--margin named with the range $c" "--margin 1e\\+06 grows the sites' bounding box beyond 1e101"
  never "no NaN $c" "nan"
done
expect 1 "tet_1e110.off: not solid with a NaN volume" -- "$dtlab" mesh check "$finds/tet_1e110.off"
never "tet_1e110.off is never called solid" "^  solid"
# sample and fracture agree: both refuse the magnitudes whose volume overflows.
expect 2 "sample tet_1e110.off" -- "$dtlab" sample "$finds/tet_1e110.off" --count 10 --out "$tmp/s110.xyz"
says "sample names the overflow" "coordinates too large"
expect 2 "fracture tet_1e110.off (not 'sampler found no site')" -- "$dtlab" fracture "$finds/tet_1e110.off" --pieces 3 --out "$tmp/f110" --quiet
says "fracture names the overflow" "coordinates too large"

# Nested shells of the same orientation: diagnosed, and united by --repair.
expect 1 "nested_same.off is not solid" -- "$dtlab" mesh check "$finds/nested_same.off"
says "nested_same.off diagnosed" "inside a shell of the same orientation"
expect 0 "mesh repair nested_same.off" -- "$dtlab" mesh repair "$finds/nested_same.off" --out "$tmp/nested_fixed.off"
expect 0 "the repaired mesh is solid" -- "$dtlab" mesh check "$tmp/nested_fixed.off"
expect 0 "fracture --repair nested_same.off" -- "$dtlab" fracture "$finds/nested_same.off" --pieces 8 --repair --out "$tmp/nf" --quiet

# --- Campaign files.
D="$tmp/camp"
expect 1 "fuzz eps 1e-12 (epsilon fails these)" -- "$dtlab" fuzz --family near_degenerate --cases 3 --predicates epsilon --eps 1e-12 --out "$D" --quiet --no-shrink
expect 2 "fuzz resume with another --eps is refused" -- "$dtlab" fuzz --family near_degenerate --cases 3 --predicates epsilon --eps 0.1 --out "$D" --quiet --no-shrink
says "the refusal names --eps" "with --eps 1e-12"
expect 2 "fuzz resume with another --points is refused" -- "$dtlab" fuzz --family near_degenerate --cases 3 --predicates epsilon --eps 1e-12 --points 20 --out "$D" --quiet --no-shrink
says "the refusal names --points" "with --points 64"
rm "$D/settings.json"
expect 2 "fuzz resume after settings.json was removed is refused" -- "$dtlab" fuzz --family near_degenerate --cases 3 --predicates epsilon --eps 0.1 --out "$D" --quiet --no-shrink
says "the refusal names the missing settings" "holds results \(results.jsonl\) but no settings.json"
"$dtlab" fuzz --family near_degenerate --cases 1 --predicates epsilon --eps 1e-12 --out "$tmp/campE" --quiet --no-shrink >/dev/null
cp "$tmp/campE/settings.json" "$D/"
expect 2 "fuzz resume with another --order is refused" -- "$dtlab" fuzz --family near_degenerate --cases 3 --predicates epsilon --eps 1e-12 --order input --out "$D" --quiet --no-shrink
says "the refusal names --order" "with --order"
# Each setting that changes outcomes (--perturb is part of the backend labels).
for pair in "--min-points 5|--min-points" "--seed 9|--seed" "--boundary bigtet|--boundary" \
  "--perturb none|--predicates" "--against cgal|--against"; do
  setting=${pair%|*}
  # shellcheck disable=SC2086
  expect 2 "fuzz resume with another $setting is refused" -- "$dtlab" fuzz --family near_degenerate --cases 3 --predicates epsilon --eps 1e-12 $setting --out "$D" --quiet --no-shrink
  says "the refusal names ${pair#*|}" "with ${pair#*|}"
done
# A results.jsonl whose last line was cut: the cut case runs again, nothing doubled.
# (campT is the probe's folder after the old resume: line 6 is a cut record with a
# whole one glued to it; here the cut is made afresh from its first five lines.)
cp -r "$finds/fuzz_cut_line/campT" "$tmp/campT"
chmod -R u+w "$tmp/campT"
# The probe's dtlab kept no settings.json: such results are not resumed (their settings
# are unknown); with the settings of the run that made them (the defaults) they are.
expect 2 "resume of results without settings.json is refused" -- "$dtlab" fuzz --family uniform --cases 6 --out "$tmp/campT" --quiet
says "the missing settings are named" "no settings.json"
"$dtlab" fuzz --family uniform --cases 1 --out "$tmp/campS" --quiet >/dev/null
cp "$tmp/campS/settings.json" "$tmp/campT/"
expect 0 "resume of the probe's folder" -- "$dtlab" fuzz --family uniform --cases 6 --out "$tmp/campT" --quiet
says "its six cases are there, none rerun" "0 cases run now, 6 resumed"
head -n 5 "$finds/fuzz_cut_line/campT/results.jsonl" > "$tmp/campT/results.jsonl"
tail -n 1 "$finds/fuzz_cut_line/campT/results.jsonl" | head -c 200 >> "$tmp/campT/results.jsonl"
expect 0 "resume of a cut results.jsonl" -- "$dtlab" fuzz --family uniform --cases 6 --out "$tmp/campT" --quiet
says "the cut case runs again" "1 cases run now, 5 resumed"
ok "6 whole records after the repair (got $(wc -l < "$tmp/campT/results.jsonl"))" \
  [ "$(wc -l < "$tmp/campT/results.jsonl")" -eq 6 ]
ok "every line is a record" "$py" -c "import json,sys; [json.loads(l) for l in open(sys.argv[1])]" "$tmp/campT/results.jsonl"
expect 0 "a second resume runs nothing" -- "$dtlab" fuzz --family uniform --cases 6 --out "$tmp/campT" --quiet
says "nothing rerun" "0 cases run now, 6 resumed"
# Two campaigns on one --out at once: the second is refused.
flock "$tmp/campT/results.jsonl" sleep 3 &
holder=$!
sleep 0.3
expect 2 "a second campaign on a locked --out" -- "$dtlab" fuzz --family uniform --cases 6 --out "$tmp/campT" --quiet
says "the lock is named" "another campaign is writing"
wait "$holder"

# --- The low rows.
for s in 0/4294967297 0/-3 1/1 a/2; do
  expect 2 "--shard $s" -- "$dtlab" fuzz --family uniform --cases 2 --shard "$s" --out "$tmp/sh" --quiet
done
for s in -1 18446744073709551616 1e23; do
  expect 2 "tetra --seed $s" -- "$dtlab" tetra "$finds/five.xyz" --seed "$s"
  expect 2 "fuzz --seed $s" -- "$dtlab" fuzz --family uniform --cases 1 --seed "$s" --out "$tmp/sd" --quiet
done
expect 0 "--seed 18446744073709551615 is a seed" -- "$dtlab" tetra "$finds/five.xyz" --seed 18446744073709551615
expect 2 "--min-points above --points" -- "$dtlab" fuzz --family uniform --cases 1 --points 10 --min-points 100 --out "$tmp/mp" --quiet
says "--min-points named" "--min-points 100 is above --points 10"
printf 'OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' > "$tmp/tet.off"
if [ -z "${DTLAB_SANITIZE:-}" ]; then
  expect 1 "out of memory is not bad input" -- bash -c "ulimit -v 300000; exec '$dtlab' sample '$tmp/tet.off' --count 1073741824 --out '$tmp/s.xyz'"
  says "out of memory named" "out of memory"
fi
expect 3 "--tetgen /bin/true is no answer" -- "$dtlab" oracle "$finds/five.xyz" --against tetgen --tetgen /bin/true
says "/bin/true refused" "refused"
expect 2 "sample --out x.ply" -- "$dtlab" sample "$tmp/tet.off" --count 10 --out "$tmp/s.ply"
ok "sample --out x.ply wrote nothing" [ ! -e "$tmp/s.ply" ]

# A witness line lists at most 16 tets, however many share the facet.
cp "$finds/rep5.node" "$tmp/rep5.node"
"$py" -c "print(200000,4,0);[print(i,1,4,2,3) for i in range(200000)]" > "$tmp/rep5.ele"
expect 1 "check rep5 (a facet shared by 200000 tets)" -- "$dtlab" check "$tmp/rep5"
ok "rep5's witness lines are short" [ "$(awk '{ if (length($0) > m) m = length($0) } END { print m }' "$tmp/out")" -lt 400 ]
says "rep5 names the count" "facet shared by 200000 tets \\(the first 16 listed\\)"

# A mesh with no tets over flat points is valid, and says why; over 3D points it is a gap.
printf '5 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 1 1 0\n4 2 3 0\n' > "$tmp/cop.node"
printf '0 4 0\n' > "$tmp/cop.ele"
expect 0 "check cop (coplanar points, no tets)" -- "$dtlab" check "$tmp/cop"
says "cop: the empty mesh is proven right" "valid: no tetrahedra; the points are coplanar \(decided exactly\), so the empty mesh is the Delaunay tetrahedralization"
says "cop: volume 0, the span named" "input spans plane: volume 0"
never "cop: no unproven cover is claimed" "cover not proven"
expect 0 "check cop --json" -- "$dtlab" check "$tmp/cop" --json
says "cop --json names the span" '"input_span": "plane"'
printf '4 3 0 0\n0 0 0 0\n1 1 1 1\n2 2 2 2\n3 3 3 3\n' > "$tmp/col.node"
cp "$tmp/cop.ele" "$tmp/col.ele"
expect 0 "check col (collinear points, no tets)" -- "$dtlab" check "$tmp/col"
says "col: collinear" "the points are collinear"
printf '5 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 1 1 0\n4 2 3 1e-300\n' > "$tmp/lift.node"
cp "$tmp/cop.ele" "$tmp/lift.ele"
expect 1 "check lift (one point 1e-300 off the plane, no tets)" -- "$dtlab" check "$tmp/lift"
says "lift: a gap, the cover not proven" "cover not proven"
says "lift: the spanning points named" "gap: no tets, but these input points span a tetrahedron; vertices \[0 1 2 4\]"

expect 2 "experiment leaderboard --cgal-data /missing" -- "$dtlab" experiment leaderboard --cgal-data "$tmp/missing.tar.gz" --out "$tmp/lb"

echo "finds2_cli: $pass passed, $fails failed"
[ "$fails" -eq 0 ]
