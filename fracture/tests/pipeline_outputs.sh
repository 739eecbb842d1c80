#!/usr/bin/env bash
# fracture's pipeline outputs on the built-in torus: surfaces.vtu integrated by VTK
# (vtkMassProperties, when python3-vtk9 is installed), the glTF's structure, the
# manifest's mass properties, islands, and the site options' errors.
#   bash fracture/tests/pipeline_outputs.sh DTLAB
set -u
dtlab=$1
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

# 6 sites, seed 1: one cell crosses the torus twice (7 pieces; 6 with --no-island-split).
"$dtlab" fracture builtin --pieces 6 --seed 1 --quiet --out "$tmp/f" --surfaces --vtu --gltf --density 2.5 >/dev/null ||
  fail "fracture --surfaces --gltf"
"$dtlab" fracture builtin --pieces 6 --seed 1 --quiet --no-island-split --json >"$tmp/whole.json" ||
  fail "fracture --no-island-split"
/usr/bin/python3 "$here/vtk_volumes.py" "$tmp/f" --tolerance 1e-9
rc=$?
[ $rc -eq 0 ] || [ $rc -eq 77 ] || fail "VTK volumes"
python3 "$here/gltf_structure.py" "$tmp/f" || fail "glTF structure"
python3 - "$tmp/f/manifest.json" "$tmp/whole.json" <<'PY' || fail "manifest mass, islands"
import json, sys
m = json.load(open(sys.argv[1]))
whole = json.load(open(sys.argv[2]))
assert len(m["pieces"]) == 7 and len(whole["pieces"]) == 6, (len(m["pieces"]), len(whole["pieces"]))
split = [p for p in m["pieces"] if p["site_islands"] == 2]
assert len(split) == 2 and split[0]["site_index"] == split[1]["site_index"]
w = whole["pieces"][split[0]["site_index"]]
assert abs(split[0]["volume"] + split[1]["volume"] - w["volume"]) <= 1e-12 * w["volume"]
# islands of one cell do not touch each other; each has its own neighbours
assert split[1]["id"] not in split[0]["neighbors"]
assert m["density"] == 2.5
for p in m["pieces"]:
    assert abs(p["mass"] - 2.5 * p["volume"]) <= 1e-15 * abs(p["mass"]), p
    assert abs(p["mass_inertia"][0][0] - 2.5 * p["inertia"][0][0]) <= 1e-12 * abs(p["mass_inertia"][0][0])
    assert 0 <= p["island"] < p["site_islands"]
    for j in p["neighbors"]:
        assert p["id"] in m["pieces"][j]["neighbors"]
print("manifest: %d pieces from %d sites" % (len(m["pieces"]), len({p["site_index"] for p in m["pieces"]})))
PY

# --tets: every piece tetrahedralized (TetGen -pY); VTK and meshio sum the tets to the
# manifest's volumes; the tets' exact volume equals each surface's; the exact tiling.
if command -v tetgen >/dev/null; then
  "$dtlab" fracture builtin --pieces 6 --seed 1 --quiet --out "$tmp/t" --tets --exact-tiling >/dev/null ||
    fail "fracture --tets --exact-tiling"
  /usr/bin/python3 "$here/tet_volumes.py" "$tmp/t" --tolerance 1e-9
  rc=$?
  [ $rc -eq 0 ] || [ $rc -eq 77 ] || fail "tet volumes"
  python3 - "$tmp/t/manifest.json" <<'PY' || fail "manifest tets, volume identity"
import json, sys
m = json.load(open(sys.argv[1]))
assert m["tets"]["pieces"] == len(m["pieces"]) == m["tets"]["pieces_exact"], m["tets"]
for p in m["pieces"]:
    assert p["tets"] > 0 and p["tet_volume_exact"], p
    assert abs(p["tet_volume"] - p["volume"]) <= 1e-12 * p["volume"], p
vi = m["volume_identity"]
assert vi["exact_tiling"]["holds"] and vi["exact_tiling"]["difference"] == 0, vi
assert abs(vi["float_relative"]) <= 1e-12 and abs(vi["exact_relative"]) <= 1e-12, vi
print("tets: %d in %d pieces, exact tiling, written coordinates off by %.1e (exact), %.1e (float)" %
      (m["tets"]["tets"], len(m["pieces"]), vi["exact_relative"], vi["float_relative"]))
PY
  # A TetGen that is not there is refused before the work (exit 2), nothing written.
  "$dtlab" fracture builtin --pieces 3 --quiet --out "$tmp/t2" --tets --tetgen /nonexistent/tetgen 2>"$tmp/err"
  rc=$?
  [ $rc -eq 2 ] && grep -q "no TetGen program /nonexistent/tetgen" "$tmp/err" && [ ! -e "$tmp/t2/manifest.json" ] ||
    fail "missing tetgen: exit $rc $(cat "$tmp/err")"
else
  echo "SKIP --tets: tetgen is not installed"
fi

# Errors: one line, exit 2.
expect2() {
  local what=$1
  shift
  "$@" >"$tmp/out" 2>"$tmp/err"
  local rc=$?
  [ $rc -eq 2 ] || fail "$what: exit $rc"
  grep -qF -- "$what" "$tmp/err" || fail "$what: $(cat "$tmp/err")"
}
printf '0 0 0\n1 nan 0\n' >"$tmp/bad.xyz"
expect2 "bad.xyz:2:" "$dtlab" fracture builtin --sites "$tmp/bad.xyz" --out "$tmp/g"
expect2 "missing.xyz:0: cannot open file" "$dtlab" fracture builtin --sites "$tmp/missing.xyz" --out "$tmp/g"
expect2 "--impact takes three" "$dtlab" fracture builtin --impact 1,2 --impact-radius 1 --out "$tmp/g"
expect2 "--impact needs --impact-radius" "$dtlab" fracture builtin --impact 1,2,3 --out "$tmp/g"
expect2 "--cell-scale takes three" "$dtlab" fracture builtin --cell-scale 1,2 --out "$tmp/g"
expect2 "cell-scale" "$dtlab" fracture builtin --cell-scale 1,0,1 --out "$tmp/g"
[ $fails -eq 0 ] && echo "pipeline outputs: all passed"
exit $((fails > 0))
