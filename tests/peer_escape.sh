#!/usr/bin/env bash
# A peer whose child leaves its process group (setsid) escapes the group kill; dtlab
# finds it by the DTLAB_GUARD tag in its environment (kernel/exit_guard.hpp) and, when
# it cleared its environment too (env -i setsid), through the program's reaper, the
# subreaper that adopts it (oracle/peers/program_reaper.hpp). The stand-in peer starts
# `[env -i] setsid sleep 7MARK` and then exits at once, or hangs; after each way dtlab
# can end it (the peer's end, its timeout, Ctrl-C to dtlab's group, SIGKILL to dtlab
# alone: the watchdog) no such sleeper may be left. Usage: peer_escape.sh DTLAB
set -u
py=/usr/bin/python3
[ -x "$py" ] || py=python3
EXPECT_TIMEOUT=60
source "$(dirname "$0")/../cli/tests/expect.sh" "$1"

mark="$$"
setsid_path=$(command -v setsid)
sleep_path=$(command -v sleep)
cat > "$tmp/esc.sh" <<SH
#!/bin/sh
# esc.sh quick|hang MARK [clear]: a sleeper in a session of its own (with an empty
# environment: clear), then exit or hang
if [ "\$3" = clear ]; then env -i $setsid_path $sleep_path "7\$2" & else setsid sleep "7\$2" & fi
sleep 0.3  # the sleeper has left the group by now
[ "\$1" = hang ] && sleep 600
exit 1
SH
chmod +x "$tmp/esc.sh"
"$py" -c "
import random
random.seed(2)
print('\n'.join('%.17g %.17g %.17g' % (random.random(), random.random(), random.random()) for _ in range(100)))" > "$tmp/p.xyz"
sleepers() { ps -eo stat=,args= | grep -v '^Z' | grep "[s]leep 7$mark"; }
none_left() {  # none_left DESCRIPTION
  for _ in $(seq 30); do [ -z "$(sleepers)" ] && break; sleep 0.1; done
  local left
  left=$(sleepers)
  ok "$1: no escaped sleeper left (${left:-none})" [ -z "$left" ]
  pkill -KILL -f "sleep 7$mark" 2>/dev/null  # so that the next case starts clean
}
for how in keep clear; do  # the environment kept (the tag finds it) or cleared (the reaper does)
  peer() { echo "esc=$tmp/esc.sh $1 $mark $how {in} {out}"; }

  expect 3 "$how: a peer that exits at once (refused: exit 3)" -- "$dtlab" oracle "$tmp/p.xyz" --against esc --peer "$(peer quick)" --quiet
  none_left "$how: the peer's end"
  expect 3 "$how: a peer that hangs, --timeout 1 (hung: exit 3)" -- "$dtlab" oracle "$tmp/p.xyz" --against esc --peer "$(peer hang)" --timeout 1 --quiet
  says "the hung peer is reported" "esc +hung"
  none_left "$how: the peer's timeout"
  expect 3 "$how: a Voronoi peer that exits at once (refused: exit 3)" -- "$dtlab" voronoi "$tmp/p.xyz" --against esc --voronoi-peer "$(peer quick)" --quiet
  none_left "$how: the Voronoi peer's end"

  # Interrupts: dtlab in a session of its own (as a shell job; SIGINT back to its default,
  # which a non-interactive shell ignores in background jobs), signalled once the peer runs.
  for sig in INT KILL; do
    "$py" -c 'import os, signal, sys; signal.signal(signal.SIGINT, signal.SIG_DFL); os.setsid(); os.execvp(sys.argv[1], sys.argv[1:])' \
      "$dtlab" oracle "$tmp/p.xyz" --against esc --peer "$(peer hang)" --quiet >/dev/null 2>&1 &
    leader=$!
    for _ in $(seq 100); do [ -n "$(sleepers)" ] && break; sleep 0.1; done
    ok "$how: SIG$sig: the sleeper started" [ -n "$(sleepers)" ]
    if [ "$sig" = KILL ]; then kill -KILL "$leader"; else kill -INT -- -"$leader"; fi
    wait "$leader"
    none_left "$how: SIG$sig to dtlab"
  done
done

# A SIGCHLD that the caller ignores is inherited across exec: the children would be
# reaped before dtlab's waits ("wait failed" for every peer). dtlab resets it.
expect 0 "SIGCHLD ignored by the caller: the cgal peer still answers" -- "$py" -c '
import os, signal, sys
signal.signal(signal.SIGCHLD, signal.SIG_IGN)
os.execv(sys.argv[1], sys.argv[1:])' "$dtlab" oracle "$tmp/p.xyz" --against cgal --quiet
says "the cgal peer's verdict" "cgal +delaunay"

# A blocked SIGTERM (a caller's signal mask, inherited across exec) would let dtlab
# ignore `timeout`'s SIGTERM: dtlab unblocks what it handles, so it ends (143).
"$py" -c '
import os, signal, sys
signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGTERM, signal.SIGINT})
os.execv(sys.argv[1], sys.argv[1:])' "$dtlab" oracle "$tmp/p.xyz" --against esc --peer "$(peer hang)" --quiet >/dev/null 2>&1 &
blocked=$!
for _ in $(seq 100); do [ -n "$(sleepers)" ] && break; sleep 0.1; done
kill -TERM "$blocked"
for _ in $(seq 50); do kill -0 "$blocked" 2>/dev/null || break; sleep 0.1; done
ok "SIGTERM blocked by the caller: dtlab still ends on it" bash -c "! kill -0 $blocked 2>/dev/null"
kill -KILL "$blocked" 2>/dev/null
wait "$blocked"
ok "... with status 143" [ $? -eq 143 ]
none_left "SIGTERM blocked by the caller"

echo "$pass passed, $fails failed"
[ "$fails" -eq 0 ]
