#!/usr/bin/env bash
# The sharded-campaign recipe of fuzz/README.md, run through GNU parallel (CTest
# fuzz_sharded_campaign): the same campaign once unsharded and as N shards, (a) each
# shard in its own folder (as on separate machines), merged by
# `dtlab fuzz --summarize A B C --out M`, and (b) all shards in one shared folder,
# summarized in place. Both summaries must equal the unsharded run's byte for byte.
# Usage: sharded_campaign.sh DTLAB OUTDIR. Exit 77 (skipped) without GNU parallel.
set -euo pipefail
dtlab=$1
out=$2
command -v parallel >/dev/null || { echo "GNU parallel not installed (scripts/setup installs it)"; exit 77; }
rm -rf "$out"
mkdir -p "$out"
campaign="fuzz --family all --cases 6 --seed 7 --predicates naive,adaptive --perturb sos --jobs 1 --no-shrink"
N=3

# exit 1 = "some case failed" (naive does): not an error here
run() { "$@" >/dev/null || [ $? -eq 1 ]; }
export -f run

run "$dtlab" $campaign --out "$out/whole"
seq 0 $((N - 1)) | parallel --halt now,fail=1 -j 2 run "$dtlab" $campaign --shard {}/$N --out "$out/shard{}"
seq 0 $((N - 1)) | parallel --halt now,fail=1 -j 2 run "$dtlab" $campaign --shard {}/$N --out "$out/shared"

"$dtlab" fuzz --summarize "$out/shard0" "$out/shard1" "$out/shard2" --out "$out/merged" >/dev/null
"$dtlab" fuzz --summarize "$out/shared" >/dev/null

status=0
for f in summary.md summary.json; do
  for d in merged shared; do
    if ! cmp -s "$out/whole/$f" "$out/$d/$f"; then
      echo "FAIL: $d/$f differs from the unsharded run's"
      diff "$out/whole/$f" "$out/$d/$f" | head -20 || true
      status=1
    fi
  done
done
# the shards really split the work, and the files a paper cites are there
for k in 0 1 2; do
  lines=$(cat "$out/shard$k"/results*.jsonl | wc -l)
  whole=$(wc -l < "$out/whole/results.jsonl")
  if [ "$lines" -eq 0 ] || [ "$lines" -ge "$whole" ]; then echo "FAIL: shard $k has $lines of $whole results"; status=1; fi
  [ -f "$out/shard$k/environment.shard-$k-of-$N.json" ] || { echo "FAIL: no environment file in shard$k"; status=1; }
done
[ -f "$out/whole/environment.json" ] || { echo "FAIL: no environment.json"; status=1; }
[ -f "$out/merged/environment.json" ] || { echo "FAIL: the merged folder has no environment.json"; status=1; }
grep -q '"dtlab_commit"' "$out/whole/results.jsonl" || { echo "FAIL: results lines carry no commit"; status=1; }
grep -q '"ci95"' "$out/whole/summary.json" || { echo "FAIL: summary.json has no intervals"; status=1; }
failures=$(grep -o '"failing": [0-9]*' "$out/whole/summary.json" | head -1 | grep -o '[0-9]*$')
[ "${failures:-0}" -gt 0 ] || { echo "FAIL: naive found no failure, the comparison is vacuous"; status=1; }
# `fuzz --replay` prints the checker's witness of a failing case, not only its kind
run "$dtlab" fuzz --family kettner_grid --cases 2 --points 24 --predicates naive --perturb none --out "$out/witness"
replay=$("$dtlab" fuzz --replay "$out/witness" || true)
if ! grep -q "^FAIL" <<<"$replay" || ! grep -q "defects:" <<<"$replay" || ! grep -Eq "point [0-9]+ \(" <<<"$replay"; then
  echo "FAIL: the replay shows no witness:"; echo "$replay" | head -20; status=1
fi
[ $status -eq 0 ] && echo "sharded summaries identical to the unsharded one ($failures failures)"
exit $status
