#!/usr/bin/env bash
# Reruns into a used folder (the sixth probe's finds 8-10): a resumed fuzz campaign
# refuses another --threads (naive builds fail differently on other counts); a rerun
# leaves no corpus entry of an earlier run beside its results (fuzz, fuzz --target with
# a Delaunay and a Voronoi peer, experiment leaderboard); an interrupted leaderboard run
# leaves no earlier run's report beside its own files, and the table scripts refuse the
# folder. Usage: campaign_reruns.sh DTLAB
set -u
py=/usr/bin/python3  # Debian's (a pyenv shim may lack what the scripts import)
[ -x "$py" ] || py=python3
EXPECT_TIMEOUT=60
source "$(dirname "$0")/../cli/tests/expect.sh" "$1"
here=$(cd "$(dirname "$0")" && pwd)
experiments="$here/../experiments"
exists() { [ -e "$1" ]; }
gone() { [ ! -e "$1" ]; }

# --- 8. --threads is a setting of the outcomes: kept in settings.json and on each line.
F="$tmp/threads"
camp=(fuzz --predicates naive --family near_degenerate,kettner_grid --cases 3 --points 60 --no-shrink --quiet --out "$F")
expect 1 "naive campaign, serial builds" -- "$dtlab" "${camp[@]}" --threads 1
expect 2 "resume with --threads 2 is refused" -- "$dtlab" "${camp[@]}" --threads 2
says "the refusal names --threads" "holds a campaign run with --threads 1, this run has 2"
expect 1 "resume without --threads (serial builds) is accepted" -- "$dtlab" "${camp[@]}"
says "nothing rerun" "0 cases run now, 6 resumed"
ok "settings.json keeps --threads 1" grep -q '"--threads": 1' "$F/settings.json"
ok "each result line keeps its threads" [ "$(grep -c '"threads":1' "$F/results.jsonl")" -eq 6 ]
expect 1 "--threads 0 into a fresh folder" -- "$dtlab" "${camp[@]/$F/$tmp/threads0}" --threads 0
ok "--threads 0 is kept as the count it resolves to ($(nproc))" grep -q "\"--threads\": $(nproc)" "$tmp/threads0/settings.json"

# --- 10. fuzz: the entries of the cases a run runs, and of resumed results that passed, go.
C="$tmp/corpus_camp"
mkdir -p "$C/corpus"
stale() { for c in "$@"; do for e in node json; do echo stale >"$C/corpus/uniform-s1-$c-adaptive+sos.$e"; done; done; }
stale 0 1 7
expect 0 "a fresh campaign into a folder with stale entries" -- "$dtlab" fuzz --family uniform --cases 2 --points 12 \
  --predicates adaptive --out "$C" --quiet
ok "the entries of the cases it ran are gone" gone "$C/corpus/uniform-s1-1-adaptive+sos.node"
ok "... their sidecars too" gone "$C/corpus/uniform-s1-0-adaptive+sos.json"
ok "the entry of a case it did not run stays" exists "$C/corpus/uniform-s1-7-adaptive+sos.node"
stale 0 1
head -n 1 "$C/results.jsonl" >"$C/r" && mv "$C/r" "$C/results.jsonl"  # case 1 runs again
expect 0 "resume: case 0 resumed, case 1 run again" -- "$dtlab" fuzz --family uniform --cases 2 --points 12 \
  --predicates adaptive --out "$C" --quiet
says "one case resumed" "1 cases run now, 1 resumed"
ok "the entry of the resumed case that passed is gone" gone "$C/corpus/uniform-s1-0-adaptive+sos.node"
ok "the entry of the case run again is gone" gone "$C/corpus/uniform-s1-1-adaptive+sos.node"
N="$tmp/naive_camp"
naive=(fuzz --family kettner_grid --cases 1 --points 20 --predicates naive,adaptive --out "$N" --quiet)
expect 1 "naive on kettner_grid fails and is shrunk" -- "$dtlab" "${naive[@]}"
entry="$N/corpus/kettner_grid-s1-0-naive+sos.node"
ok "its failure is in the corpus" exists "$entry"
grep -v '"backend":"adaptive+sos"' "$N/results.jsonl" >"$N/r" && mv "$N/r" "$N/results.jsonl"
expect 1 "resume: the case runs again for adaptive only" -- "$dtlab" "${naive[@]}"
says "the case ran again" "1 cases run now, 0 resumed"
ok "the resumed naive failure keeps its entry" exists "$entry"
ok "... and its sidecar" exists "${entry%.node}.json"

# fuzz --target, a Delaunay peer: a wrong `mine`, then a right one of the same name.
cat >"$tmp/drop.sh" <<SH
#!/usr/bin/env bash
"$dtlab" tetra "\$1" --out "\$2.tmp" >/dev/null || exit 1
t=\$(head -1 "\$2.tmp.ele" | cut -d' ' -f1)
{ echo "\$((t - 1)) 4 0"; sed -n "2,\${t}p" "\$2.tmp.ele"; } >"\$2.ele"
SH
chmod +x "$tmp/drop.sh"
T="$tmp/target"
target=(fuzz --target mine --family uniform --cases 1 --min-points 8 --points 8 --shrink-budget 20 --quiet --out "$T")
expect 1 "fuzz --target a wrong mine" -- "$dtlab" "${target[@]}" --peer "mine=$tmp/drop.sh {in} {out}"
ok "its failure is in the corpus" exists "$T/corpus/mine-uniform-n8-0.node"
echo stale >"$T/corpus/other-uniform-n8-0.node"
expect 0 "fuzz --target a right mine" -- "$dtlab" "${target[@]}" --peer "mine=$dtlab tetra {in} --out {out}"
ok "the wrong peer's failure is gone" gone "$T/corpus/mine-uniform-n8-0.node"
ok "... and its sidecar" gone "$T/corpus/mine-uniform-n8-0.json"
ok "another peer's entry stays" exists "$T/corpus/other-uniform-n8-0.node"

# fuzz --target, a Voronoi peer (a name with '+', kept; it was written as 'p'): a rerun that shrinks
# nothing leaves none of the first run's entries.
V="$tmp/vtarget"
vtarget=(fuzz --target v+1 --voronoi-peer "v+1=/bin/false {in} {box} {out}" --family uniform --cases 1 --points 8
  --shrink-budget 5 --quiet --out "$V")
expect 1 "fuzz --target a Voronoi peer that always fails" -- "$dtlab" "${vtarget[@]}"
ok "its failure is in the corpus" exists "$V/corpus/v+1-uniform-n8-0.node"
expect 1 "the same campaign with --no-shrink" -- "$dtlab" "${vtarget[@]}" --no-shrink
ok "the first run's entry is gone" gone "$V/corpus/v+1-uniform-n8-0.node"

# --- 9, 10. The leaderboard: a rerun removes the earlier run's files before its first.
L="$tmp/board"
board=(experiment leaderboard --out "$L" --quick --peers none --family uniform --cases 1 --no-meshes
  --voronoi-speed 100 --quiet)
expect 0 "leaderboard, a failing Voronoi peer" -- "$dtlab" "${board[@]}" --voronoi-peers bad \
  --voronoi-peer "bad=/bin/false {in} {box} {out}"
ok "its failure is in voronoi/corpus" exists "$L/voronoi/corpus/bad-uniform-n48-0.node"
expect 0 "leaderboard rerun with another peer" -- "$dtlab" "${board[@]}" --voronoi-peers dtlab:adaptive
ok "the earlier peer's entry is gone" gone "$L/voronoi/corpus/bad-uniform-n48-0.node"
ok "... and its sidecar" gone "$L/voronoi/corpus/bad-uniform-n48-0.json"
expect 0 "voronoi_table.py reads the whole run" -- "$py" "$experiments/voronoi_table.py" "$L"
says "the table names the run's peer" "dtlab:adaptive"
# A third run into the folder, stopped by SIGINT while its Voronoi peer runs.
printf '#!/bin/sh\nsleep 30.%s\n' "$$" >"$tmp/slow.sh"
chmod +x "$tmp/slow.sh"
running() { pgrep -f "sleep 30.$$" >/dev/null; }
"$py" "$here/finds2/launch.py" "$tmp/int.out" "$dtlab" "${board[@]}" --voronoi-peers slow \
  --voronoi-peer "slow=$tmp/slow.sh {in} {box} {out}" &
launcher=$!
for _ in $(seq 100); do running && break; sleep 0.1; done
ok "the slow peer started" running
kill -INT -- -"$launcher"
wait "$launcher"
got=$?
ok "SIGINT: exit $got, expected 130" [ "$got" -eq 130 ]
for _ in $(seq 30); do running || break; sleep 0.1; done
ok "no peer left running" bash -c "! pgrep -f '[s]leep 30.$$' >/dev/null"
for f in report.md report.html data/facts.json data/voronoi.csv data/voronoi_speed.csv; do
  ok "the interrupted run left no earlier $f" gone "$L/$f"
done
expect 1 "voronoi_table.py refuses the interrupted run" -- "$py" "$experiments/voronoi_table.py" "$L"
says "it names the missing mark" "no data/facts.json"
expect 1 "leaderboard_table.py refuses it too" -- "$py" "$experiments/leaderboard_table.py" "$L"
says "it names the missing mark" "no data/facts.json"

# A fuzz campaign's folder is not a leaderboard's: its corpus is not cleaned away.
expect 2 "leaderboard into a fuzz campaign's folder" -- "$dtlab" experiment leaderboard --out "$F" --quick --peers none \
  --family uniform --cases 1 --no-meshes --voronoi-speed 100 --quiet
says "the refusal names the campaign" "holds a fuzz campaign"
ok "the campaign's results are kept" exists "$F/results.jsonl"

echo "campaign_reruns: $pass passed, $fails failed"
[ "$fails" -eq 0 ]
