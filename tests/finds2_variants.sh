#!/usr/bin/env bash
# Variants of the second probe's classes (tests/finds2/README.txt) on the readers,
# commands and Python functions its rows did not name (issue 24's held-out variants):
# unchecked writes, magnitudes a double cannot measure, integer options that wrapped,
# and range checks that lived in the CLI only. Each check fails on the code before.
# Usage: finds2_variants.sh DTLAB [PYTHONPATH of the dtlab module]
set -u
pypath="${2:-}"
py=/usr/bin/python3  # Debian's, with numpy
[ -x "$py" ] || py=python3
EXPECT_TIMEOUT=120
source "$(dirname "$0")/../cli/tests/expect.sh" "$1"

# --- A failed write is exit 2 naming the file, never "wrote": the PNG and the
# per-piece files of fracture went around the checked writer (kernel/output_file.hpp).
expect 2 "fracture --png onto a full device" -- "$dtlab" fracture builtin --pieces 2 --out "$tmp/fp" --png /dev/full --quiet
says "the PNG write is named" "/dev/full:0: write failed: No space left on device"
mkdir -p "$tmp/fs/pieces"
ln -s /dev/full "$tmp/fs/pieces/piece_0001.obj"
expect 2 "fracture --split, a piece file on a full device" -- "$dtlab" fracture builtin --pieces 2 --out "$tmp/fs" --split --quiet
says "the piece file is named" "piece_0001.obj:0: write failed"
never "no 'wrote' line after a failed write" "^wrote"

# --- A UTF-8 byte order mark (skipped in .xyz, OFF, OBJ, .node) in STL and PLY too; an
# ASCII STL may begin with blanks. Both were taken for binary or "not a PLY file".
tri() { printf 'facet normal 0 0 0\nouter loop\nvertex %s\nvertex %s\nvertex %s\nendloop\nendfacet\n' "$@"; }
{ echo "solid t"; tri "0 0 0" "0 1 0" "1 0 0"; tri "0 0 0" "1 0 0" "0 0 1"; tri "0 0 0" "0 0 1" "0 1 0"
  tri "1 0 0" "0 1 0" "0 0 1"; echo "endsolid t"; } > "$tmp/tet.stl"
printf '\xef\xbb\xbf' | cat - "$tmp/tet.stl" > "$tmp/bom.stl"
expect 0 "an ASCII STL after a BOM" -- "$dtlab" mesh check "$tmp/bom.stl"
{ printf '\n  '; cat "$tmp/tet.stl"; } > "$tmp/blank.stl"
expect 0 "an ASCII STL after blanks" -- "$dtlab" mesh check "$tmp/blank.stl"
printf '\xef\xbb\xbfply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' > "$tmp/bom.ply"
expect 0 "a PLY after a BOM" -- "$dtlab" mesh check "$tmp/bom.ply"

# --- Magnitudes: a double measures a tet of side 1e80 (area 1e160, volume 1e239) and of
# side 1e-100; below (volume under 1e-308) it is "coordinates too small", as above it is
# "too large", for mesh check, sample and fracture alike.
tet() { printf 'OFF\n4 4 0\n0 0 0\n%s 0 0\n0 %s 0\n0 0 %s\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' "$1" "$1" "$1" > "$2"; }
tet 1e80 "$tmp/t80.off"
expect 0 "mesh check, a tet of side 1e80 is solid" -- "$dtlab" mesh check "$tmp/t80.off"
expect 0 "sample, a tet of side 1e80" -- "$dtlab" sample "$tmp/t80.off" --count 10 --out "$tmp/s80.xyz"
expect 0 "sample --method surface, a tet of side 1e80" -- "$dtlab" sample "$tmp/t80.off" --method surface --count 10 --out "$tmp/s80s.xyz"
tet 1e-90 "$tmp/t-90.off"
expect 0 "sample --method surface, a tet of side 1e-90" -- "$dtlab" sample "$tmp/t-90.off" --method surface --count 10 --out "$tmp/s90.xyz"
ok "10 surface points at 1e-90" [ "$(wc -l < "$tmp/s90.xyz")" -eq 10 ]
for s in 1e-110 1e-160 1e-300; do
  tet "$s" "$tmp/t$s.off"
  expect 1 "mesh check, a tet of side $s is not solid" -- "$dtlab" mesh check "$tmp/t$s.off"
  says "mesh check $s: too small, not 'encloses no volume'" "coordinates too small: the area or volume underflows a double"
  never "mesh check $s never calls it empty" "encloses no volume"
  expect 2 "sample, a tet of side $s" -- "$dtlab" sample "$tmp/t$s.off" --count 10 --out "$tmp/s$s.xyz"
  says "sample $s names the underflow" "coordinates too small"
  ok "sample $s wrote nothing" [ ! -e "$tmp/s$s.xyz" ]
  expect 2 "fracture, a tet of side $s" -- "$dtlab" fracture "$tmp/t$s.off" --pieces 3 --out "$tmp/f$s" --quiet
  says "fracture $s names the underflow (not the gap)" "coordinates too small"
done

# --- Integer options: "-1" no longer wraps to 2^64-1 (as --seed did), "1e0" is 1.
expect 2 "fracture --recurse -1 is refused before any work" -- "$dtlab" fracture builtin --pieces 3 --recurse -1 --out "$tmp/fr"
says "--recurse -1 named" "--recurse: '-1' is not in \\[0, 1e\\+09\\]"
never "--recurse -1: no boolean ran" "booleans"
expect 0 "fracture --recurse 1e0 is piece 1" -- "$dtlab" fracture builtin --pieces 3 --recurse 1e0 --out "$tmp/fr" --quiet
expect 2 "leaderboard --voronoi-speed -1" -- "$dtlab" experiment leaderboard --quick --voronoi-speed -1 --out "$tmp/lb"
says "--voronoi-speed -1 named" "--voronoi-speed: '-1' is not in"

# --- Python: the CLI's rules in the shared code, so dtlab.voronoi, dtlab.sample and
# dtlab.fracture refuse what the commands refuse (they returned NaN cells, ran 4 million
# candidates, or returned no piece).
if [ -n "$pypath" ] && PYTHONPATH="$pypath" "$py" -c "import dtlab" 2>/dev/null; then
  cp "$(dirname "$0")/finds2/tet_1e110.off" "$(dirname "$0")/finds2/ulp.xyz" "$(dirname "$0")/finds2/mix.xyz" "$tmp/"
  expect 0 "python refuses what the CLI refuses" -- env PYTHONPATH="$pypath" "$py" - "$tmp" <<'EOF'
import sys, numpy as np, dtlab
tmp = sys.argv[1]
P = np.random.default_rng(1).random((20, 3))
def refused(what, want, f):
    try:
        f()
    except ValueError as e:
        assert want in str(e), (what, str(e))
        return
    raise SystemExit(what + ": accepted")
refused("voronoi box 1e200", "box: expected a number in [-1e+101, 1e+101]", lambda: dtlab.voronoi(P, box=(-1e200,) * 3 + (1e200,) * 3))
refused("voronoi sites 1e155", "beyond 1e100", lambda: dtlab.voronoi(P * 1e155))
refused("voronoi sites 1e-300", "less than 1e-100", lambda: dtlab.voronoi(P * 1e-300))
for name in ("ulp", "mix"):  # sites one ulp apart, 2^+-1000 mixes: lost cells are refused
    refused("voronoi " + name, "", lambda: dtlab.voronoi(np.loadtxt(tmp + "/" + name + ".xyz")))
refused("sample tet 1e110", "coordinates too large", lambda: dtlab.sample(tmp + "/tet_1e110.off", 20))
refused("sample tet 1e-160", "coordinates too small", lambda: dtlab.sample(tmp + "/t1e-160.off", 20))
m = dtlab.read_mesh(tmp + "/t80.off")
v, f = (m.vertices, m.faces) if hasattr(m, "vertices") else m
refused("fracture margin 1e300", "not smaller than the mesh", lambda: dtlab.fracture(v, f, pieces=3, margin=1e300))
refused("fuzz.campaign points 1e12 (was std::bad_alloc as a ValueError)", "points: expected an integer in [1, 10000000], got 1000000000000",
        lambda: dtlab.fuzz.campaign("dtlab:adaptive", "uniform", cases=1, points=10**12))
assert len(dtlab.voronoi(P).cells) == 20
print("ok")
EOF
  says "python: all refused" "^ok"
  # Ctrl-C reaches tetrahedralize() and voronoi() without progress= too (they waited for
  # the whole build: 30 s for 1.5e6 points), on one thread and on two.
  cat > "$tmp/py_int.py" <<'EOF'
import sys, numpy as np
import dtlab
from sigint_self import interrupted_within
what, threads = sys.argv[1], int(sys.argv[2])
pts = np.random.default_rng(1).random((1000000, 3))
call = (lambda: dtlab.tetrahedralize(pts, threads=threads)) if what == "tetrahedralize" else (lambda: dtlab.voronoi(pts))
sys.exit(interrupted_within(1.0, 2.0, call))
EOF
  for case in "tetrahedralize 1" "tetrahedralize 2" "voronoi 1"; do
    # shellcheck disable=SC2086
    expect 0 "python $case thread(s) + SIGINT answers within 2 s" -- env PYTHONPATH="$pypath:$(dirname "$0")" "$py" "$tmp/py_int.py" $case
    says "python $case: KeyboardInterrupt" "interrupted [01]\\.[0-9]+ s after the signal"
  done
else
  echo "finds2_variants: the Python checks skipped (no dtlab module with numpy)"
fi

echo "finds2_variants: $pass passed, $fails failed"
[ "$fails" -eq 0 ]
