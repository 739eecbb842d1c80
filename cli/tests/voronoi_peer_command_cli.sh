#!/usr/bin/env bash
# Voronoi peers given by a command (`--voronoi-peer NAME=COMMAND`, peers-file entries
# with kind = "voronoi"): a scipy.spatial.Voronoi wrapper gets the built-in
# scipy-voronoi peer's verdicts on every fuzz family, voro++'s command line wrapped with
# no code gets the linked voro++'s topology, fuzz --target shrinks an external peer's
# failure to a 1-minimal input with a command that replays it, and every way a command
# can misbehave is a verdict (or a one-line message with exit 2), nothing left running.
#   voronoi_peer_command_cli.sh DTLAB [--full]   (--full: 5 cases per family, label slow)
set -u
. "$(dirname "$0")/expect.sh"
full=${2:-}
examples=$(cd "$(dirname "$0")/../../examples/voronoi_peers" && pwd)
py=/usr/bin/python3
mine="mine=$py $examples/scipy_voronoi.py {in} {box} {out}"
"$dtlab" sample builtin --count 60 --seed 3 --out "$tmp/pts.xyz" >/dev/null 2>&1

# (a) The wrapper and the built-in peer: the same verdict on every case of every family.
same_campaign() {  # same_campaign DESCRIPTION FAMILIES CASES POINTS PEER-A PEER-B [options of B...]
  local what=$1 families=$2 cases=$3 points=$4 a=$5 b=$6
  shift 6
  "$dtlab" fuzz --target "$a" --family "$families" --cases "$cases" --points "$points" --no-shrink --json --quiet \
    --out "$tmp/ca" >"$tmp/a.json" 2>/dev/null
  "$dtlab" fuzz --target "$b" "$@" --family "$families" --cases "$cases" --points "$points" --no-shrink --json --quiet \
    --out "$tmp/cb" >"$tmp/b.json" 2>/dev/null
  $py - "$tmp/a.json" "$tmp/b.json" <<'PY' && pass=$((pass + 1)) || { echo "FAIL: $what"; fails=$((fails + 1)); }
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
fam = lambda j: {s: (r["cases"], r["failing"], r["verdicts"]) for s, r in j["families"].items()}
fails = lambda j: sorted((f["source"], f["case"], f["verdict"]) for f in j["failures"])
assert a["cases"] == b["cases"] and a["not_installed"] == b["not_installed"] == 0, (a["cases"], b["cases"])
assert fam(a) == fam(b), [(s, fam(a)[s], fam(b).get(s)) for s in fam(a) if fam(a)[s] != fam(b).get(s)]
assert fails(a) == fails(b), (fails(a), fails(b))
total = {}
for r in a["families"].values():
    for v, k in r["verdicts"].items():
        total[v] = total.get(v, 0) + k
print("  %d cases, %d failing, the same verdicts: %s" % (a["cases"], a["failing"], dict(sorted(total.items()))))
PY
}
if [ "$full" = --full ]; then
  same_campaign "scipy wrapper = scipy-voronoi, 5 cases x 18 families" all 5 64 scipy-voronoi mine --voronoi-peer "$mine"
else
  same_campaign "scipy wrapper = scipy-voronoi, 1 case x 18 families" all 1 32 scipy-voronoi mine --voronoi-peer "$mine"
fi
# Faces in any orientation: every other face reversed, the same verdicts.
same_campaign "faces reversed" uniform,lattice,cospherical,duplicates 1 24 scipy-voronoi flip --voronoi-peer "flip=$py $examples/scipy_voronoi.py --flip-faces {in} {box} {out}"

# voro++'s own command line, no code: {sites} is its input file, so it writes {out}.vol.
# It prints vertices with 6 digits (%g), so its geometry is off by ~1e-6 (bad-geometry
# or volume-mismatch); its topology must be the linked voro++'s.
vpp='vpp=voro++ -c "%i %w %P %s %n %t" -o {xmin} {xmax} {ymin} {ymax} {zmin} {zmax} {sites}'
if command -v voro++ >/dev/null; then
  expect 0 "voro++ command line" -- "$dtlab" voronoi "$tmp/pts.xyz" --against voro++,vpp --voronoi-peer "$vpp" --json --quiet
  $py - "$tmp/out" <<'PY' && pass=$((pass + 1)) || { echo "FAIL: voro++ CLI topology"; fails=$((fails + 1)); }
import json, sys
p = json.load(open(sys.argv[1]))["peers"]
assert p["voro++"]["verdict"] == "exact-topology", p["voro++"]["verdict"]
assert p["vpp"]["topology"] == "exact-topology" and p["vpp"]["cells"] == 60, p["vpp"]
assert 1e-9 < p["vpp"]["max_vertex_error"] < 1e-4, p["vpp"]["max_vertex_error"]
PY
  cases=1; [ "$full" = --full ] && cases=5
  for fam in lattice duplicates cospherical; do
    "$dtlab" fuzz --target voro++ --family $fam --cases $cases --points 40 --no-shrink --json --quiet --out "$tmp/v1" >"$tmp/a.json" 2>/dev/null
    "$dtlab" fuzz --target vpp --voronoi-peer "$vpp" --family $fam --cases $cases --points 40 --no-shrink --json --quiet \
      --out "$tmp/v2" >"$tmp/b.json" 2>/dev/null
    $py - "$tmp/a.json" "$tmp/b.json" <<'PY' && pass=$((pass + 1)) || { echo "FAIL: voro++ CLI vs linked on $fam"; fails=$((fails + 1)); }
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
wrong = lambda j: sorted((f["source"], f["case"]) for f in j["failures"] if f["verdict"] == "wrong-topology")
assert wrong(a) == wrong(b), (wrong(a), wrong(b))
PY
  done
else
  echo "skip: no voro++ command line (Debian voro++)"
fi

# (b) fuzz --target shrinks an external peer's failure: this one writes dtlab's own cells
# (the Python module) but drops the cell of site 0 whenever there are 9 sites or more,
# so a 1-minimal input has 9 sites. (scipy cannot be its base: it has no ridges at all
# on 4 sites, so a shrink of a scipy-based peer ends at 4.)
cat >"$tmp/drop.py" <<PY
import json, sys
sys.path.insert(0, "$(cd "$(dirname "$dtlab")/../python" && pwd)")
import dtlab, numpy as np
node, box, out = sys.argv[1], [float(x) for x in sys.argv[2:8]], sys.argv[8]
rows = [l.split() for l in open(node) if l.strip() and not l.startswith("#")]
pts = np.array([[float(x) for x in r[1:4]] for r in rows[1:1 + int(rows[0][0])]])
d = dtlab.voronoi(pts, box=box)
cells = [{"site": i, "vertices": c.vertices.tolist(), "faces": [f.tolist() for f in c.faces],
          "neighbors": [int(j) for j in c.face_neighbors]} for i, c in enumerate(d.cells) if len(c.faces)]
if len(pts) >= 9:
    cells = [c for c in cells if c["site"] != 0]
json.dump({"cells": cells}, open(out + ".json", "w"))
PY
# Under the asan preset the module drop.py imports is instrumented too: its interpreter
# needs the runtime preloaded, as python/CMakeLists.txt does for the Python tests.
droppy="$py"
if asan=$(ldd "$dtlab" 2>/dev/null | grep -o '/[^ ]*libasan\.so[^ ]*'); then
  cxx=$(ldd "$dtlab" | grep -o '/[^ ]*libstdc++\.so[^ ]*' || true)
  printf '#!/bin/sh\nLD_PRELOAD="%s %s" ASAN_OPTIONS=detect_leaks=0 exec %s "$@"\n' "$asan" "$cxx" "$py" >"$tmp/py_asan"
  chmod +x "$tmp/py_asan"
  droppy="$tmp/py_asan"
fi
drop="drop=$droppy $tmp/drop.py {in} {box} {out}"
expect 1 "fuzz --target a wrong Voronoi command peer" -- "$dtlab" fuzz --target drop --voronoi-peer "$drop" \
  --family uniform --cases 1 --min-points 14 --points 14 --out "$tmp/f3" --quiet
has() { grep -qE -- "$1" "$tmp/out" || { echo "FAIL: $2: no '$1' in"; sed 's/^/  | /' "$tmp/out" "$tmp/err" | head -20; fails=$((fails + 1)); }; }
has "uniform case 0: wrong-topology, shrunk to 9 points \(1-minimal\)" "the failure listed"
has "--voronoi-peer 'drop=" "the listed replay defines the peer"
side=$(ls "$tmp/f3/corpus/"*.json 2>/dev/null | head -1)
$py - "$side" <<'PY' && pass=$((pass + 1)) || { echo "FAIL: shrunk sidecar"; fails=$((fails + 1)); }
import json, sys
j = json.load(open(sys.argv[1]))
assert j["points"] == 9 and j["minimal"] and j["shrunk_verdict_fresh"] == "wrong-topology", j
assert "--voronoi-peer 'drop=" in j["command"] and "--voronoi-peer 'drop=" in j["original_command"], j
PY
node=$(ls "$tmp/f3/corpus/"*.node | head -1)
expect 0 "replaying the shrunk input" -- "$dtlab" voronoi "$node" --against drop --voronoi-peer "$drop" --quiet
has "^drop: wrong-topology \(missing-cell 1" "still fails when replayed"

# (c) Misbehaving commands: each a verdict, never a crash of dtlab.
cat >"$tmp/emit.py" <<'PY'
# emit.py KIND OUT: writes a cells file of one kind of garbage to OUT.json (or .vol)
import json, sys
kind, out = sys.argv[1], sys.argv[2]
cube = {"site": 0, "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0], [0, 0, 1], [1, 0, 1], [0, 1, 1], [1, 1, 1]],
        "faces": [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]],
        "neighbors": [-5, -6, -3, -4, -1, -2]}
if kind == "garbage": open(out + ".json", "w").write("bananas\n")
if kind == "nultail": open(out + ".json", "w").write(json.dumps({"cells": [cube]}) + "\n\0\0")
if kind == "line3": open(out + ".json", "w").write('{"cells": [\n\n  bananas]}\n')
if kind == "nan": open(out + ".json", "w").write(json.dumps({"cells": [dict(cube, vertices=[[float("nan"), 0, 0]] + cube["vertices"][1:])]}))
if kind == "range": open(out + ".json", "w").write(json.dumps({"cells": [dict(cube, faces=[[0, 2, 99, 1]] + cube["faces"][1:])]}))
if kind == "site": open(out + ".json", "w").write(json.dumps({"cells": [dict(cube, site=999)]}))
if kind == "count": open(out + ".json", "w").write(json.dumps({"cells": [dict(cube, neighbors=[-1])]}))
if kind == "field": open(out + ".json", "w").write(json.dumps({"cells": [dict(cube, nbrs=[])]}))
# A duplicated key (nlohmann keeps the last: the cells, or the site, replaced without a word).
if kind == "dupcells": open(out + ".json", "w").write('{"cells": [%s], "cells": []}' % json.dumps(cube))
if kind == "dupsite": open(out + ".json", "w").write('{"cells": [%s, %s]}' % (json.dumps(cube), json.dumps(cube).replace('"site": 0', '"site": 0, "site": 1')))
if kind == "wall7": open(out + ".json", "w").write(json.dumps({"cells": [dict(cube, neighbors=[-5, -6, -3, -4, -1, -7])]}))
if kind == "volwall7": open(out + ".vol", "w").write("0 4 (0,0,0) (1,0,0) (0,1,0) (0,0,1) 4 -1 -3 -5 -7 (0,2,1) (0,1,3) (0,3,2) (1,2,3)\n")
if kind == "volnan": open(out + ".vol", "w").write("0 3 (nan,0,0) (1,0,0) (0,1,0) 1 -1 (0,1,2)\n")
if kind == "bigexp": open(out + ".json", "w").write(json.dumps({"cells": [cube]}).replace("[1, 0, 0]", "[1e400, 0, 0]", 1))
if kind == "vol": open(out + ".vol", "w").write("0 3 (0,0,0) (1,0,0) 1 -1 (0,1,2)\n")
if kind == "chatty":
    print("hello on stdout"); print('{"not": "dtlab"}')
PY
verdict() {  # verdict DESCRIPTION PEER-COMMAND EXIT PATTERN [dtlab voronoi options...]
  local what=$1 command=$2 code=$3 pattern=$4
  shift 4
  expect "$code" "$what" -- "$dtlab" voronoi "$tmp/pts.xyz" --against p --voronoi-peer "p=$command" --quiet "$@"
  has "$pattern" "$what"
}
chatty="$py $tmp/emit.py chatty {out}"
verdict "garbage" "$py $tmp/emit.py garbage {out} {in}" 3 "^p: refused: unreadable answer: out.json:1: not JSON: syntax error"
verdict "a second \"cells\"" "$py $tmp/emit.py dupcells {out} {in}" 3 "^p: refused: unreadable answer: out.json: duplicate field 'cells'"
verdict "a second \"site\" in cell 1" "$py $tmp/emit.py dupsite {out} {in}" 3 "^p: refused: unreadable answer: out.json: cells\[1\]: duplicate field 'site'"
verdict "a wall tag -7" "$py $tmp/emit.py wall7 {out} {in}" 3 "^p: refused: unreadable answer: out.json: cells\[0\].neighbors\[5\]: -7 out of range \[-6, "
verdict "a .vol wall tag -7" "$py $tmp/emit.py volwall7 {out} {in}" 3 "^p: refused: unreadable answer: out.vol:1: a neighbour id \\(a site, or -1..-6 for a wall\\): expected an integer in \[-6, "
verdict "NaN (not JSON)" "$py $tmp/emit.py nan {out} {in}" 3 "^p: refused: unreadable answer: out.json:1: not JSON"
verdict "a face vertex out of range" "$py $tmp/emit.py range {out} {in}" 3 \
  "^p: refused: unreadable answer: out.json: cells\[0\].faces\[0\]\[2\]: 99 out of range \[0, 7\]"
verdict "one neighbour for six faces" "$py $tmp/emit.py count {out} {in}" 3 "cells\[0\].neighbors: 1 neighbours for 6 faces"
verdict "an unknown field" "$py $tmp/emit.py field {out} {in}" 3 "cells\[0\]: unknown field 'nbrs'"
verdict "a number beyond a double (docs/probe3.md)" "$py $tmp/emit.py bigexp {out} {in}" 3 "^p: refused: unreadable answer: out.json: not JSON: number overflow parsing '1e400'"
verdict "a .vol vertex NaN" "$py $tmp/emit.py volnan {out} {in}" 3 "unreadable answer: out.vol:1: a vertex is not finite"
verdict "a .vol line short of a vertex" "$py $tmp/emit.py vol {out} {in}" 3 "unreadable answer: out.vol:1: a vertex \(x,y,z\): expected \(a,b,...\), got '1'"
verdict "a NUL after the JSON value" "$py $tmp/emit.py nultail {out} {in}" 3 \
  "^p: refused: unreadable answer: out.json:2: not JSON: a NUL byte \\(byte [0-9]+\\)"
verdict "a JSON error on line 3" "$py $tmp/emit.py line3 {out} {in}" 3 "^p: refused: unreadable answer: out.json:3: not JSON: syntax error"
grep -q "NUL" "$tmp/out" && { echo "FAIL: a JSON syntax error called a NUL byte"; fails=$((fails + 1)); } || pass=$((pass + 1))
# A 1000 MB sparse answer of NUL bytes (docs/probe3.md: read whole, twice, before it was
# refused): refused at its first byte, dtlab's peak RSS far below the file's size.
cat >"$tmp/rss.py" <<'PY'
# rss.py OUT COMMAND...: runs COMMAND, writes its peak RSS (KiB, the largest of its processes) to OUT
import resource, subprocess, sys
rc = subprocess.run(sys.argv[2:]).returncode
open(sys.argv[1], "w").write("%d\n" % resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
sys.exit(rc)
PY
for ext in json vol; do
  expect 3 "a sparse NUL .$ext answer" -- $py "$tmp/rss.py" "$tmp/rss" "$dtlab" voronoi "$tmp/pts.xyz" --against p --quiet \
    --voronoi-peer "p=/bin/sh -c 'truncate -s 1000M \"\$1.$ext\"' {in} {out}"
  case $ext in
    json) has "^p: refused: unreadable answer: out.json:1: not JSON: a NUL byte \\(byte 1\\)" "NUL JSON refused at its first byte" ;;
    vol) has "^p: refused: unreadable answer: out.vol:1: byte 0x00 at column 1: not a text file" "NUL .vol refused at its first byte" ;;
  esac
  [ "$(cat "$tmp/rss")" -lt 300000 ] && pass=$((pass + 1)) \
    || { echo "FAIL: a sparse NUL .$ext answer: peak RSS $(cat "$tmp/rss") KiB (the file read whole)"; fails=$((fails + 1)); }
done
verdict "a cell of no site" "$py $tmp/emit.py site {out} {in}" 0 "^p: wrong-topology \(.*missing-cell 60.*extra-cell 1"
verdict "no cells file" "/bin/true {in} {out}" 3 "^p: refused: exited 0 but wrote no \{out\}.json"
verdict "exit 5" "/bin/sh -c 'echo cannot do this >&2; exit 5' {in} {out}" 3 "^p: refused: cannot do this"
verdict "a crash" "/bin/sh -c 'kill -SEGV \$\$' {in} {out}" 3 "^p: crashed: signal 11"
verdict "a program that does not exist" "/nonexistent/prog {in} {out}" 3 "^p: not-installed"
verdict "never exits" "/bin/sh -c 'sleep 27.1828 & sleep 27.1828' {in} {out}" 3 "^p: hung: killed after" --timeout 1
sleep 0.2
if pgrep -f "sleep 27.1828" >/dev/null; then echo "FAIL: the hung peer's processes are still running"; fails=$((fails + 1)); else pass=$((pass + 1)); fi
# Printing on stdout is harmless (its stdout goes to its log): --json stays one object.
cat >"$tmp/chatty.sh" <<SH
#!/usr/bin/env bash
echo "hello from the peer on stdout"; echo '{"not": "dtlab"}'
exec $py $examples/scipy_voronoi.py "\$@"
SH
chmod +x "$tmp/chatty.sh"
expect 0 "a peer that prints on stdout" -- "$dtlab" voronoi "$tmp/pts.xyz" --against chatty --voronoi-peer "chatty=$tmp/chatty.sh {in} {box} {out}" --json --quiet
$py -c 'import json,sys; j = json.load(open(sys.argv[1])); assert j["peers"]["chatty"]["verdict"] == "exact-topology", j["peers"]' "$tmp/out" \
  && pass=$((pass + 1)) || { echo "FAIL: --json not one object, or chatty not exact"; fails=$((fails + 1)); }

# A box smaller than the sites' hull (docs/probe3.md): sites outside it get empty cells,
# neither refused as lost cells nor --check defects, and the dtlab:exact peer answers too.
expect 0 "--box inside the hull, --check" -- "$dtlab" voronoi "$tmp/pts.xyz" --box 0.3 0.3 0.3 0.6 0.6 0.6 --check --against dtlab:exact --quiet
has "^check: 0 defect" "no defect for the empty cells of sites outside the box"
has "^dtlab:exact: exact-topology" "the dtlab:exact peer answers"
expect 0 "--box beside every site" -- "$dtlab" voronoi "$tmp/pts.xyz" --box 5 5 5 6 6 6 --quiet
# A box far larger than the sites (docs/probe3.md, --margin 1e4..1e6): --check's cell
# tolerance is of the cells' scale (cell_scale), not of the box diagonal, so the cells'
# real edges of 1e-5 are no "zero-length edge" where the exact checker finds nothing.
$py -c 'import random; random.seed(7); print("\n".join("%r %r %r" % tuple(random.random() for _ in "xyz") for _ in range(200)))' >"$tmp/u200.xyz"
for m in 1e4 1e5; do
  expect 0 "--margin $m --check --against dtlab:exact" -- "$dtlab" voronoi "$tmp/u200.xyz" --margin $m --check \
    --against dtlab:exact --quiet
  has "^check: 0 defect" "--margin $m: no --check defect"
  has "^dtlab:exact: exact-topology" "--margin $m: the exact checker agrees"
done
# ... and the cells themselves are the sites' (the clip band and choose_cell of cell_scale):
# a box of +-1e10 lost 313 faces (band 0.035), +-1e30..1e100 was refused as "sites too close".
for b in 1e10 1e30 1e100; do
  expect 0 "--box +-$b --check --against dtlab:exact" -- "$dtlab" voronoi "$tmp/u200.xyz" --box -$b -$b -$b $b $b $b \
    --check --against dtlab:exact --quiet
  has "^check: 0 defect" "--box +-$b: no --check defect"
  has "^dtlab: exact-topology" "--box +-$b: our cells exact"
done
expect 0 "--margin 1e6 --check --against dtlab:exact" -- "$dtlab" voronoi "$tmp/u200.xyz" --margin 1e6 --check \
  --against dtlab:exact --quiet
has "^check: 0 defect" "--margin 1e6: no --check defect"
has "^dtlab: exact-topology" "--margin 1e6: our cells exact"

# Bad definitions: exit 2, one line naming the problem.
bad() {  # bad DESCRIPTION PATTERN dtlab-arguments...
  local what=$1 pattern=$2
  shift 2
  expect 2 "$what" -- "$dtlab" "$@"
  grep -qE -- "$pattern" "$tmp/err" && [ "$(wc -l <"$tmp/err")" -eq 1 ] && pass=$((pass + 1)) \
    || { echo "FAIL: $what: no one line /$pattern/ in"; sed 's/^/  | /' "$tmp/err" | head; fails=$((fails + 1)); }
}
bad "no {in}" "--voronoi-peer: Voronoi peer 'p': the command has no \{in\} or \{sites\}" voronoi "$tmp/pts.xyz" --voronoi-peer "p=prog {out}"
bad "no {out}" "has no \{out\}" voronoi "$tmp/pts.xyz" --voronoi-peer "p=prog {in} {box}"
bad "unknown placeholder" "unknown placeholder '\{boxx\}'" fuzz --target p --voronoi-peer "p=prog {in} {boxx} {out}" --out "$tmp/f0"
bad "{box} inside a word" "\{box\} must be a whole argument" voronoi "$tmp/pts.xyz" --voronoi-peer "p=prog --box={box} {in} {out}"
bad "a built-in Voronoi peer's name" "'voro\+\+' is a built-in peer's" voronoi "$tmp/pts.xyz" --voronoi-peer "voro++=prog {in} {out}"
bad "a built-in Delaunay peer's name" "'cgal' is a built-in Delaunay peer's" voronoi "$tmp/pts.xyz" --voronoi-peer "cgal=prog {in} {out}"
bad "one name, two kinds" "'q' names a Delaunay peer \(--peer\) too" fuzz --target q --peer "q=a {in} {out}" --voronoi-peer "q=b {in} {out}" --out "$tmp/f0"
bad "an unknown Voronoi peer" "unknown Voronoi peer 'nosuch'" voronoi "$tmp/pts.xyz" --against nosuch

# A peers file with both kinds, JSON and TOML; kind is checked.
cat >"$tmp/peers.json" <<JSON
{"peers": [{"name": "self", "command": "$dtlab tetra {in} --out {out}"},
           {"name": "mine", "kind": "voronoi", "command": ["$py", "$examples/scipy_voronoi.py", "{in}", "{box}", "{out}"]}]}
JSON
expect 0 "peers file, JSON" -- "$dtlab" voronoi "$tmp/pts.xyz" --against mine --peers "$tmp/peers.json" --quiet
has "^mine: exact-topology" "a Voronoi peer from a JSON peers file"
printf '[[peers]]\nname = "mine"\nkind = "voronoi"\ncommand = "%s %s/scipy_voronoi.py {in} {box} {out}"\n' "$py" "$examples" >"$tmp/peers.toml"
expect 0 "peers file, TOML" -- "$dtlab" voronoi "$tmp/pts.xyz" --against mine --peers "$tmp/peers.toml" --quiet
has "^mine: exact-topology" "a Voronoi peer from a TOML peers file"
printf '[[peers]]\nname = "m"\nkind = "voronio"\ncommand = "prog {in} {out}"\n' >"$tmp/kind.toml"
bad "an unknown kind" "kind.toml:4: peer 1: unknown kind 'voronio' \(delaunay, voronoi\)" voronoi "$tmp/pts.xyz" --peers "$tmp/kind.toml"
printf '{"peers": [{"name": "m", "kind": "voronoi", "command": "prog {in}"}]}\n' >"$tmp/noout.json"
bad "a Voronoi entry without {out}" "noout.json:0: peer 1: Voronoi peer 'm': the command has no \{out\}" voronoi "$tmp/pts.xyz" --peers "$tmp/noout.json"

# experiment leaderboard: a --voronoi-peer gets its own row in the Voronoi section.
expect 0 "leaderboard with a Voronoi command peer" -- "$dtlab" experiment leaderboard --quick --peers cgal --family uniform \
  --cases 1 --no-meshes --speed-n 500 --voronoi-peers voro++ --voronoi-peer "$mine" --voronoi-speed 500 --out "$tmp/lb" --quiet
grep -q '^mine,uniform,' "$tmp/lb/data/voronoi.csv" && grep -q '^voro++,uniform,' "$tmp/lb/data/voronoi.csv" \
  && pass=$((pass + 1)) || { echo "FAIL: no Voronoi row for the command peer"; head -5 "$tmp/lb/data/voronoi.csv"; fails=$((fails + 1)); }

echo "$pass passed, $fails failed"
[ "$fails" -eq 0 ]
