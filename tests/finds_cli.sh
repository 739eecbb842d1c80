#!/usr/bin/env bash
# The inputs and commands that once broke dtlab (tests/finds/README.txt), each with the
# behaviour the README promises: exit 0 valid, 1 a defect or named build failure,
# 2 bad usage or input with a message naming the file; no hang, no NaN passed off as
# a result, no "wrote" after a failed write.
set -u
finds="$2"
EXPECT_TIMEOUT=60
source "$(dirname "$0")/../cli/tests/expect.sh" "$1"
cli="$finds/cli"

# An axis extent in (0, 5.7e-306): the Hilbert order's NaN (spatial_order.cpp).
expect 0 "cli_subnormal_axis.xyz tetra" -- "$dtlab" tetra "$finds/cli_subnormal_axis.xyz" --out "$tmp/sub"
expect 0 "cli_subnormal_axis.xyz check" -- "$dtlab" check "$tmp/sub"

# bigtet: an enclosing tet that overflows is a named failure; a bad FACTOR and a flat input are exit 2.
expect 1 "e307.xyz bigtet" -- "$dtlab" tetra "$cli/e307.xyz" --boundary bigtet
says "e307.xyz bigtet names the failure" "outside-boundary"
expect 0 "e307.xyz infinite" -- "$dtlab" tetra "$cli/e307.xyz"
expect 2 "five.node bigtet:1e-20" -- "$dtlab" tetra "$cli/five.node" --boundary bigtet:1e-20
expect 2 "five.node bigtet:inf" -- "$dtlab" tetra "$cli/five.node" --boundary bigtet:inf
expect 2 "five.node bigtet:nan" -- "$dtlab" tetra "$cli/five.node" --boundary bigtet:nan
expect 1 "five.node bigtet:1 (point 0 on the tet's face)" -- "$dtlab" tetra "$cli/five.node" --boundary bigtet:1
says "five.node bigtet:1 names the failure" "outside-boundary"
expect 0 "five.node bigtet:2" -- "$dtlab" tetra "$cli/five.node" --boundary bigtet:2
expect 2 "coplanar.xyz bigtet" -- "$dtlab" tetra "$cli/coplanar.xyz" --boundary bigtet
says "coplanar.xyz bigtet message" "coplanar"

# Voronoi: a NaN volume error fails --check; NaN options are refused.
expect 2 "huge_range.xyz voronoi (box overflows)" -- "$dtlab" voronoi "$cli/huge_range.xyz" --check
says "huge_range.xyz voronoi message" "overflow"
expect 2 "five.node voronoi --check, a box beyond the range is refused (issue 24)" -- \
  "$dtlab" voronoi "$cli/five.node" --check --box -1e200 -1e200 -1e200 1e200 1e200 1e200
expect 2 "five.node voronoi --margin nan" -- "$dtlab" voronoi "$cli/five.node" --margin nan --check
expect 2 "five.node voronoi --margin -5" -- "$dtlab" voronoi "$cli/five.node" --margin -5
expect 0 "five.node voronoi --check" -- "$dtlab" voronoi "$cli/five.node" --check

# Hangs.
expect 0 "fuzz --case 1e14 jumps to the case" -- "$dtlab" fuzz --family uniform --case 100000000000000 --out "$tmp/camp"
expect 2 "oracle --timeout nan" -- "$dtlab" oracle "$cli/five.node" --against tetgen --tetgen "$cli/slowtg.sh" --timeout nan
expect 2 "oracle --timeout -1" -- "$dtlab" oracle "$cli/five.node" --against tetgen --tetgen "$cli/slowtg.sh" --timeout -1
# slowtg.sh's own child (sleep) must die with it: a copy that records the sleep's pid.
printf '#!/bin/sh\nsleep 100 &\necho $! > "%s/sleep.pid"\nwait\n' "$tmp" > "$tmp/slowtg_pid.sh"
chmod +x "$tmp/slowtg_pid.sh"
start=$(date +%s)
expect_any() { timeout 60 "$@" >"$tmp/out" 2>"$tmp/err"; }
expect_any "$dtlab" oracle "$cli/five.node" --against tetgen --tetgen "$tmp/slowtg_pid.sh" --timeout 1
if [ $(( $(date +%s) - start )) -gt 30 ]; then echo "FAIL: oracle --timeout 1 took too long"; fails=$((fails + 1)); else pass=$((pass + 1)); fi
says "oracle time-out reported" "tetgen  *hung"
sleep 0.5
# Alive means a state other than Z (a killed child of a dead shell may wait as a zombie).
if [ -s "$tmp/sleep.pid" ] && ps -o stat= -p "$(cat "$tmp/sleep.pid")" | grep -qv Z; then
  echo "FAIL: the time-out left the tetgen script's child running"; kill "$(cat "$tmp/sleep.pid")"; fails=$((fails + 1))
else pass=$((pass + 1)); fi
expect 0 "slowtg.sh exists and runs" -- test -x "$cli/slowtg.sh"

# Meshes whose volume overflows: reported as such, no "-nan".
for m in tet_1e103.off tet_1e200.off; do
  expect 2 "$m sample" -- "$dtlab" sample "$cli/$m" --out "$tmp/s.xyz"
  says "$m sample message" "overflows"
  never "$m sample prints no nan" "nan"
done

# Extreme magnitudes: the robust backends stay valid.
for p in maxdbl.xyz mixed_mag.xyz subnormal.xyz; do
  expect 0 "$p tetra" -- "$dtlab" tetra "$cli/$p" --out "$tmp/x"
  expect 0 "$p check" -- "$dtlab" check "$tmp/x"
done

# fracture: NaN and oversized options.
expect 2 "fracture --margin nan" -- "$dtlab" fracture builtin --pieces 2 --margin nan
expect 2 "fracture --explode nan" -- "$dtlab" fracture builtin --pieces 2 --explode nan
expect 2 "fracture --margin 1e300" -- "$dtlab" fracture builtin --pieces 2 --margin 1e300
# --tets with a TetGen that is not there: refused before the work (it was exit 1 after it).
expect 2 "fracture --tets --tetgen /nonexistent" -- "$dtlab" fracture builtin --pieces 2 --tets --tetgen /nonexistent/tetgen --out "$tmp/ftg"
says "fracture --tets --tetgen /nonexistent names it" "no TetGen program /nonexistent/tetgen"
expect 2 "fracture --tets --tetgen not in PATH" -- "$dtlab" fracture builtin --pieces 2 --tets --tetgen no-such-tetgen-here --out "$tmp/ftg"

# Write errors: /dev/full.
if [ -w /dev/full ]; then
  mkdir -p "$tmp/full"
  ln -s /dev/full "$tmp/full/full.node"
  ln -s /dev/full "$tmp/full/full.ele"
  expect 2 "tetra --out on a full disk" -- "$dtlab" tetra "$cli/five.node" --out "$tmp/full/full"
  says "write error names the file" "full/full\.node.*write failed"
  never "no 'wrote' after a failed write" "^wrote"
  ln -s /dev/full "$tmp/full/pts.xyz"
  expect 2 "sample --out on a full disk" -- "$dtlab" sample builtin --count 100 --out "$tmp/full/pts.xyz"
  ln -s /dev/full "$tmp/full/cells.json"
  expect 2 "voronoi --out on a full disk" -- "$dtlab" voronoi "$cli/five.node" --out "$tmp/full/cells" --no-obj
fi

# bench: sizes and runs are validated.
for bad in "--sizes 1e30" "--sizes nan" "--sizes -5" "--runs 0"; do
  expect 2 "bench $bad" -- "$dtlab" bench $bad --tools dtlab
  never "bench $bad: no 309-digit numbers" "[0-9]{40}"
done

# oracle on too few points or an empty file: exit 2 like tetra.
printf '0 0 0\n1 0 0\n0 1 0\n' > "$tmp/three.xyz"
: > "$tmp/empty.xyz"
expect 2 "oracle on 3 points" -- "$dtlab" oracle "$tmp/three.xyz" --against cgal
expect 2 "oracle on an empty file" -- "$dtlab" oracle "$tmp/empty.xyz" --against cgal
expect 2 "fuzz --summarize on a missing folder" -- "$dtlab" fuzz --summarize --out "$tmp/no_such_campaign"

# Messages: a directory, a number out of range (not echoed in full).
mkdir -p "$tmp/dir.ply" "$tmp/dir.xyz"
expect 2 "a directory given as a mesh" -- "$dtlab" sample "$tmp/dir.ply" --out "$tmp/s.xyz"
says "directory message" "dir\.ply:0: is a directory"
expect 2 "a directory given as points" -- "$dtlab" tetra "$tmp/dir.xyz"
says "directory message (points)" "dir\.xyz:0: is a directory"
printf '0 0 0\n1 0 0\n0 1 0\n0 0 1e999\n' > "$tmp/big.xyz"
expect 2 "1e999 in a file" -- "$dtlab" tetra "$tmp/big.xyz"
says "1e999 message" "big\.xyz:4: number out of range"
printf '0 0 0\n1 0 0\n0 1 0\n0 0 1%0400d\n' 0 > "$tmp/long.xyz"
expect 2 "a 400-digit number in a file" -- "$dtlab" tetra "$tmp/long.xyz"
never "no 400-digit echo" "[0-9]{100}"
expect 2 "--eps nan" -- "$dtlab" tetra "$cli/five.node" --predicates epsilon --eps nan
expect 2 "--eps 1e999" -- "$dtlab" tetra "$cli/five.node" --predicates epsilon --eps 1e999
says "--eps 1e999 message" "out of range"

echo "$pass passed, $fails failed"
[ "$fails" -eq 0 ]
