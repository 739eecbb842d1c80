#!/usr/bin/env bash
# Predicate plug-ins (`--predicates plugin:PATH.so`) and `dtlab predicates conformance`:
# the naive plug-in fails the same fuzz cases as the built-in naive backend with the same
# outcomes, with and without sos; the exact plug-in fails none; a library without the
# symbols is refused with exit 2; the conformance suite passes the exact backends and
# reports the sign errors of naive and epsilon.
# Usage: plugin_cli.sh DTLAB NAIVE.so EXACT.so MISSING_SYMBOL.so
set -u
. "$(dirname "$0")/expect.sh"
naive_so=$2 exact_so=$3 missing_so=$4
has_err() {
  grep -qE -- "$1" "$tmp/err" || { echo "FAIL: $2: no '$1' in stderr"; sed 's/^/  | /' "$tmp/err" | head -20; fails=$((fails + 1)); }
}

# The same outcomes, case by case, as the built-in naive backend (bit for bit the same decisions).
fams=near_degenerate,ulp_jitter,kettner_grid,clustered,extreme_scale,subnormal
expect 1 "fuzz naive vs plugin naive" -- "$dtlab" fuzz --family $fams --cases 12 --points 40 --no-shrink \
  --predicates naive,plugin:$naive_so --perturb sos,none --out "$tmp/same" --quiet
python3 - "$tmp/same" <<'PY' && pass=$((pass + 1)) || { echo "FAIL: plug-in naive and naive differ"; fails=$((fails + 1)); }
import glob, json, sys
rows = [json.loads(l) for f in glob.glob(sys.argv[1] + "/results*.jsonl") for l in open(f)]
by = {}
for r in rows:
    kind = "plugin" if r["predicates"].startswith("plugin:") else r["predicates"]
    by[(kind, r["perturb"], r["id"])] = (r["outcome"], r["tets"], json.dumps(r["defects"], sort_keys=True))
naive = {k[1:]: v for k, v in by.items() if k[0] == "naive"}
plugin = {k[1:]: v for k, v in by.items() if k[0] == "plugin"}
assert len(naive) == 2 * 6 * 12 and naive.keys() == plugin.keys(), (len(naive), len(plugin))
diff = [k for k in naive if naive[k] != plugin[k]]
assert not diff, diff[:5]
failing = sum(v[0] not in ("valid", "lower-dimensional") for v in naive.values())
assert failing > 10, failing  # the families do make naive fail
print("naive and plug-in naive: %d cases, %d failing, identical outcomes" % (len(naive), failing))
PY
expect 0 "fuzz with the exact plug-in fails nothing" -- "$dtlab" fuzz --family $fams --cases 6 --points 40 \
  --predicates plugin:$exact_so --perturb sos,none --out "$tmp/exact" --quiet

# Bad plug-ins: exit 2 and one line naming the problem.
expect 2 "a library without dtlab_insphere" -- "$dtlab" tetra "$tmp/none.xyz" --predicates plugin:$missing_so
has_err "^dtlab tetra: --predicates: plugin .*: no symbol dtlab_insphere" "missing symbol message"
expect 2 "a file that is not a library" -- "$dtlab" fuzz --family uniform --predicates plugin:/etc/hostname --out "$tmp/x"
has_err "cannot load" "not a library message"
expect 2 "no such plug-in" -- "$dtlab" bench --sizes 100 --tools dtlab --predicates plugin:/nonexistent/p.so
expect 2 "unknown backend" -- "$dtlab" tetra "$tmp/none.xyz" --predicates fast

# Every other command that builds takes it: tetra --check, bench, oracle's dtlab:plugin: peer.
"$dtlab" sample builtin --count 500 --seed 2 --out "$tmp/pts.xyz" >/dev/null 2>&1
expect 0 "tetra with the exact plug-in, checked" -- "$dtlab" tetra "$tmp/pts.xyz" --predicates plugin:$exact_so --check
expect 0 "bench with the naive plug-in" -- "$dtlab" bench --sizes 1000 --tools dtlab --runs 1 --predicates plugin:$naive_so --quiet
expect 0 "oracle with dtlab:plugin: peers" -- "$dtlab" oracle "$tmp/pts.xyz" \
  --against cgal,dtlab:plugin:$exact_so,dtlab:plugin:$naive_so+none
grep -q "dtlab vs dtlab:plugin:$exact_so: agree" "$tmp/out" && pass=$((pass + 1)) || { echo "FAIL: plug-in peer not compared"; cat "$tmp/out"; fails=$((fails + 1)); }

# The conformance suite: exact backends pass, naive and epsilon are reported failing.
for b in adaptive exact interval "plugin:$exact_so"; do
  expect 0 "conformance of $b" -- "$dtlab" predicates conformance --predicates "$b" --builds 3
done
for b in naive epsilon "plugin:$naive_so"; do
  expect 1 "conformance of $b" -- "$dtlab" predicates conformance --predicates "$b" --builds 3 --json
  python3 -c '
import json, sys
j = json.load(open(sys.argv[1]))
err = {s["class"]: s["errors"] for s in j["signs"] if s["predicate"] == "orient3d"}
assert err["random"] == 0 and err["kettner-grid"] > 0 and err["near-degenerate x2^-500"] > 0, err
assert j["failed_builds"] > 0, j["failed_builds"]' "$tmp/out" && pass=$((pass + 1)) || { echo "FAIL: conformance report of $b"; fails=$((fails + 1)); }
done
# The naive plug-in's report is the built-in naive's, number for number.
"$dtlab" predicates conformance --predicates naive --json | python3 -c 'import json,sys; j=json.load(sys.stdin); j.pop("backend"); print(json.dumps(j, sort_keys=True))' >"$tmp/a"
"$dtlab" predicates conformance --predicates plugin:$naive_so --json | python3 -c 'import json,sys; j=json.load(sys.stdin); j.pop("backend"); print(json.dumps(j, sort_keys=True))' >"$tmp/b"
cmp -s "$tmp/a" "$tmp/b" && pass=$((pass + 1)) || { echo "FAIL: conformance of the naive plug-in differs from naive"; fails=$((fails + 1)); }

echo "$pass passed, $fails failed"
[ "$fails" -eq 0 ]
