#!/usr/bin/env bash
# Interrupts of the long commands beyond `oracle` (finds2_cli.sh covers oracle, bench and
# Python): `fuzz --against`, `fuzz --target`, `experiment leaderboard`, `voronoi --against`
# and `fracture --tets` with a peer that never answers, and `experiment benchmark` with
# CGAL and TetGen. Each runs in a session
# of its own and gets SIGINT (to its process group, as Ctrl-C), SIGTERM, SIGHUP or, to
# dtlab alone, SIGKILL once a child runs; then the exit status is the shell's
# (130/143/129/137), no process of that session is left (ps) and the temp folder holds
# nothing of dtlab's. Usage: finds2_signals.sh DTLAB FINDS2_DIR
set -u
finds="$2"
py=/usr/bin/python3
[ -x "$py" ] || py=python3
EXPECT_TIMEOUT=60
source "$(dirname "$0")/../cli/tests/expect.sh" "$1"

mark="9$$"  # the stand-in peer's sleep, unique to this run
printf '#!/bin/sh\nsleep 5%s\n' "$mark" > "$tmp/slow.sh"
chmod +x "$tmp/slow.sh"
# Processes of session SID other than its leader, zombies aside.
others() { ps -eo sid=,pid=,stat=,args= | awk -v s="$1" '$1 == s && $2 != s && $3 !~ /^Z/'; }
# interrupt NAME SIGNAL WANT_EXIT cmd...: runs cmd in a new session (tests/finds2/launch.py)
# with TMPDIR a fresh folder, signals it once a child of dtlab runs.
interrupt() {
  local name=$1 sig=$2 want=$3 td="$tmp/t-$1-$2"
  shift 3
  mkdir -p "$td"
  TMPDIR="$td" "$py" "$finds/launch.py" "$tmp/$name-$sig.out" "$@" &
  local leader=$!
  for _ in $(seq 300); do [ -n "$(others "$leader")" ] && break; sleep 0.1; done
  ok "$name $sig: a child of dtlab started" [ -n "$(others "$leader")" ]
  sleep 0.3
  if [ "$sig" = KILL ]; then kill -KILL "$leader"; else kill -"$sig" -- -"$leader"; fi
  wait "$leader"
  local got=$?
  ok "$name $sig: exit $got, expected $want" [ "$got" -eq "$want" ]
  for _ in $(seq 50); do [ -z "$(others "$leader")" ] && break; sleep 0.1; done
  local left
  left=$(others "$leader")
  ok "$name $sig: nothing of its session left running (${left:-none})" [ -z "$left" ]
  ok "$name $sig: no stand-in peer left" bash -c "! { ps -eo stat,args | grep -v '^Z' | grep -q '[s]leep 5$mark'; }"
  for _ in $(seq 30); do [ -z "$(ls -A "$td")" ] && break; sleep 0.1; done
  ok "$name $sig: the temp folder holds nothing of dtlab's ($(ls -A "$td" | head -3 | tr '\n' ' '))" [ -z "$(ls -A "$td")" ]
}

# The issue's case: `timeout -s INT 3 dtlab oracle big.xyz --against all`.
"$py" -c "
import random
random.seed(1)
print('\\n'.join('%.17g %.17g %.17g' % (random.random(), random.random(), random.random()) for _ in range(200000)))" > "$tmp/big.xyz"
mkdir -p "$tmp/t-timeout"
TMPDIR="$tmp/t-timeout" "$py" "$finds/launch.py" "$tmp/timeout.out" timeout -s INT 3 "$dtlab" oracle "$tmp/big.xyz" --against all --quiet &
leader=$!
wait "$leader"
got=$?
ok "timeout -s INT 3 oracle --against all: exit $got, expected 124 (timeout's)" [ "$got" -eq 124 ]
for _ in $(seq 50); do [ -z "$(others "$leader")" ] && break; sleep 0.1; done
left=$(others "$leader")
ok "timeout -s INT 3 oracle --against all: nothing of its session left (${left:-none})" [ -z "$left" ]
for _ in $(seq 30); do [ -z "$(ls -A "$tmp/t-timeout")" ] && break; sleep 0.1; done
ok "timeout -s INT 3 oracle --against all: the temp folder is empty" [ -z "$(ls -A "$tmp/t-timeout")" ]

for s in "INT 130" "TERM 143" "HUP 129" "KILL 137"; do
  set -- $s
  interrupt oracle-all "$1" "$2" "$dtlab" oracle "$tmp/big.xyz" --against all --quiet
  interrupt fuzz-against "$1" "$2" "$dtlab" fuzz --family uniform --cases 3 --against slow \
    --peer "slow=$tmp/slow.sh {in} {out}" --out "$tmp/fa-$1" --quiet --no-shrink
  interrupt fuzz-target "$1" "$2" "$dtlab" fuzz --family uniform --cases 3 --target slow \
    --peer "slow=$tmp/slow.sh {in} {out}" --out "$tmp/ft-$1" --quiet --no-shrink
  interrupt leaderboard "$1" "$2" "$dtlab" experiment leaderboard --quick --no-meshes --family uniform \
    --peers slow --peer "slow=$tmp/slow.sh {in} {out}" --out "$tmp/lb-$1" --quiet
  interrupt benchmark "$1" "$2" "$dtlab" experiment benchmark --max-n 1000000 --runs 1 --out "$tmp/bm-$1" \
    --no-figures --quiet
  # Beyond the probe's rows: a Voronoi peer by command, and fracture's TetGen (--tets).
  interrupt voronoi-against "$1" "$2" "$dtlab" voronoi "$finds/five.xyz" --against slow \
    --voronoi-peer "slow=$tmp/slow.sh {in} {out}" --out "$tmp/va-$1" --quiet
  interrupt fracture-tets "$1" "$2" "$dtlab" fracture builtin --pieces 2 --tets --tetgen "$tmp/slow.sh" \
    --out "$tmp/fx-$1" --quiet
done

echo "finds2_signals: $pass passed, $fails failed"
[ "$fails" -eq 0 ]
