#!/usr/bin/env bash
# `dtlab oracle` and `dtlab fuzz --target` as a user runs them: verdicts per peer,
# exit codes 0 (ok), 1 (dtlab wrong), 2 (bad usage), 3 (some peer gave no answer).
set -u
. "$(dirname "$0")/expect.sh"
has() {  # has PATTERN DESCRIPTION: the last command's stdout matches
  grep -qE -- "$1" "$tmp/out" || { echo "FAIL: $2: no '$1' in"; sed 's/^/  | /' "$tmp/out" | head -20; fails=$((fails + 1)); }
}

"$dtlab" sample builtin --count 400 --seed 3 --out "$tmp/pts.xyz" >/dev/null 2>&1
expect 0 "oracle against cgal and tetgen" -- "$dtlab" oracle "$tmp/pts.xyz" --against cgal,tetgen
has "^  cgal +delaunay" "cgal's verdict"
has "dtlab vs tetgen: agree" "comparison line"
has "^OK" "status"

expect 0 "oracle --json" -- "$dtlab" oracle "$tmp/pts.xyz" --against cgal,dtlab:exact --json
has '"dtlab:exact": \{' "peers keyed by name"
has '"verdict": "delaunay"' "verdict field"
has '"peak_rss_bytes"' "memory field"

# A peer that cannot run: no answer, "not compared", exit 3.
expect 3 "missing peer helper" -- env DTLAB_PEER=/nonexistent/dtlab_peer "$dtlab" oracle "$tmp/pts.xyz" --against cgal
has "not-installed" "not-installed verdict"
has "not compared: cgal" "not compared"
expect 3 "missing tetgen" -- "$dtlab" oracle "$tmp/pts.xyz" --against tetgen --tetgen /nonexistent/tetgen
expect 2 "unknown peer" -- "$dtlab" oracle "$tmp/pts.xyz" --against nosuchpeer
expect 2 "NaN timeout" -- "$dtlab" oracle "$tmp/pts.xyz" --timeout nan
expect 2 "negative timeout" -- "$dtlab" oracle "$tmp/pts.xyz" --timeout -1

# A non-robust build that is wrong is reported as dtlab's defect, with counts.
python3 - "$tmp/sphere.xyz" <<'PY'
import sys
# Points of an integer lattice rotated by a float rotation: near-cospherical everywhere.
import math
c, s = math.cos(0.3), math.sin(0.3)
with open(sys.argv[1], "w") as f:
    for i in range(12):
        for j in range(12):
            for k in range(12):
                x, y, z = i * 0.1, j * 0.1, k * 0.1
                f.write("%.17g %.17g %.17g\n" % (c * x - s * y, s * x + c * y, z))
PY
expect 1 "naive build is wrong" -- "$dtlab" oracle "$tmp/sphere.xyz" --against cgal --predicates naive --perturb none
has "dtlab's result is wrong: " "wrong-result line"

# fuzz --target judges a peer; its failures are shrunk into the corpus.
expect 0 "fuzz --target cgal" -- "$dtlab" fuzz --target cgal --family uniform,kettner_grid --cases 3 --out "$tmp/t1"
expect 1 "fuzz --target dtlab:naive+none" -- "$dtlab" fuzz --target dtlab:naive+none --family near_degenerate,kettner_grid \
  --cases 6 --points 40 --shrink-budget 60 --out "$tmp/t2"
ls "$tmp/t2/corpus/"*.node >/dev/null 2>&1 || { echo "FAIL: no shrunk input in the corpus"; fails=$((fails + 1)); }
f=$(ls "$tmp/t2/corpus/"*.node | head -1)
expect 1 "the shrunk input still fails" -- "$dtlab" oracle "$f" --against dtlab:naive+none,cgal --predicates naive --perturb none
has "dtlab:naive\+none +(invalid|missing-points|flat-tets|triangulation|crashed|hung|refused)" "peer still fails"
expect 0 "fuzz --oracle qhull-qj,cgal" -- "$dtlab" fuzz --family uniform --cases 2 --oracle cgal,qhull-qj --out "$tmp/t3"

echo "$pass passed, $fails failed"
[ "$fails" -eq 0 ]
