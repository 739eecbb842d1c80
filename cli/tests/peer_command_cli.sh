#!/usr/bin/env bash
# Peers given by a command (`--peer NAME=COMMAND`, `--peers FILE`): the same verdicts
# as a built-in adapter, every way a command can misbehave turned into a verdict or a
# one-line message with exit 2, nothing left running, and fuzz --target shrinking an
# external peer's failure into the corpus with a command that replays it.
set -u
. "$(dirname "$0")/expect.sh"
examples=$(cd "$(dirname "$0")/../../examples/peers" && pwd)
has() {  # has PATTERN DESCRIPTION: the last command's stdout matches
  grep -qE -- "$1" "$tmp/out" || { echo "FAIL: $2: no '$1' in"; sed 's/^/  | /' "$tmp/out" "$tmp/err" | head -20; fails=$((fails + 1)); }
}
has_err() {
  grep -qE -- "$1" "$tmp/err" || { echo "FAIL: $2: no '$1' in stderr"; sed 's/^/  | /' "$tmp/err" | head -20; fails=$((fails + 1)); }
}
"$dtlab" sample builtin --count 300 --seed 5 --out "$tmp/pts.xyz" >/dev/null 2>&1
self="$dtlab tetra {in} --out {out}"   # dtlab itself as a command: .node and .ele, 0-based

# A good peer: dtlab's own tetra as a command is proven Delaunay and agrees.
expect 0 "dtlab tetra as a command peer" -- "$dtlab" oracle "$tmp/pts.xyz" --against cgal,self --peer "self=$self"
has "^  self +delaunay" "the command peer's verdict"
has "dtlab vs self: agree" "compared with ours"
# Its .node removed and the .ele renumbered from 1: the base comes from the first tet's number.
cat >"$tmp/one_based.sh" <<SH
#!/usr/bin/env bash
"$dtlab" tetra "\$1" --out "\$2.tmp" >/dev/null || exit 1
awk 'NR == 1 { print; next } /^#/ { next } { print \$1 + 1, \$2 + 1, \$3 + 1, \$4 + 1, \$5 + 1 }' "\$2.tmp.ele" >"\$2.ele"
SH
chmod +x "$tmp/one_based.sh"
expect 0 "1-based .ele without .node" -- "$dtlab" oracle "$tmp/pts.xyz" --against one --peer "one=$tmp/one_based.sh {in} {out}"
has "^  one +delaunay" "1-based verdict"
# The points renumbered (reversed) in its own .node: mapped back by coordinates.
cat >"$tmp/renumber.py" <<'PY'
import subprocess, sys
dtlab, node, out = sys.argv[1:4]
subprocess.run([dtlab, "tetra", node, "--out", out + ".tmp"], check=True, stdout=subprocess.DEVNULL)
pts = [l.split() for l in open(out + ".tmp.node") if l.strip() and not l.startswith("#")][1:]
n = len(pts)
with open(out + ".node", "w") as f:
    f.write("%d 3 0 0\n" % n)
    for i in range(n):
        f.write("%d %s %s %s\n" % (i + 1, *pts[n - 1 - i][1:4]))
tets = [l.split() for l in open(out + ".tmp.ele") if l.strip() and not l.startswith("#")][1:]
with open(out + ".ele", "w") as f:
    f.write("%d 4 0\n" % len(tets))
    for t in tets:
        f.write("%s %s\n" % (t[0], " ".join(str(n - int(v)) for v in t[1:5])))
PY
expect 0 "own renumbered .node" -- "$dtlab" oracle "$tmp/pts.xyz" --against renum --peer "renum=python3 $tmp/renumber.py $dtlab {in} {out}"
has "^  renum +delaunay" "renumbered verdict"

# A peers file, JSON, the command as a string or an argv array.
cat >"$tmp/peers.json" <<JSON
{"peers": [{"name": "self", "command": "$dtlab tetra {in} --out {out}"},
           {"name": "self2", "command": ["$dtlab", "tetra", "{in}", "--out", "{out}"]}]}
JSON
expect 0 "peers file" -- "$dtlab" oracle "$tmp/pts.xyz" --against self,self2 --peers "$tmp/peers.json"
has "^  self2 +delaunay" "argv-array peer"
printf '{"peers": [\n  {"name": "x", "command": "a {in} {out}"},\n  oops\n]}\n' >"$tmp/bad.json"
expect 2 "peers file that is not JSON" -- "$dtlab" oracle "$tmp/pts.xyz" --peers "$tmp/bad.json"
has_err "bad.json:3: not JSON" "file:line of the JSON error"
printf '{"peers": [{"name": "x", "command": "prog {in}"}]}\n' >"$tmp/noout.json"
expect 2 "peers file entry without {out}" -- "$dtlab" oracle "$tmp/pts.xyz" --peers "$tmp/noout.json"
has_err "noout.json:0: peer 1: .*no \{out\}" "file and entry named"
expect 2 "missing peers file" -- "$dtlab" oracle "$tmp/pts.xyz" --peers "$tmp/none.json"
# The same peers in TOML: the same run (verdicts, tets, agreement) as from the JSON file.
cat >"$tmp/peers.toml" <<TOML
# two ways to give the command
[[peers]]
name = "self"
command = "$dtlab tetra {in} --out {out}"

[[peers]]
name = "self2"
command = ["$dtlab", "tetra", "{in}", "--out", "{out}"]
TOML
"$dtlab" oracle "$tmp/pts.xyz" --against self,self2 --peers "$tmp/peers.json" --json >"$tmp/from_json.json" 2>/dev/null
expect 0 "peers file, TOML" -- "$dtlab" oracle "$tmp/pts.xyz" --against self,self2 --peers "$tmp/peers.toml" --json
python3 - "$tmp/from_json.json" "$tmp/out" <<'PY' || { echo "FAIL: JSON and TOML peers files gave different runs"; fails=$((fails + 1)); }
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
strip = lambda j: {k: {f: v for f, v in p.items() if "seconds" not in f and f != "peak_rss_bytes"} for k, p in j["peers"].items()}
assert (a["exit"], a["problems"], strip(a)) == (b["exit"], b["problems"], strip(b)), (a, b)
assert set(a["peers"]) == {"self", "self2"} and all(p["verdict"] == "delaunay" for p in a["peers"].values())
PY
# Bad TOML: one line, file:line, exit 2.
printf '[[peers]]\nname = "x"\ncommand = "a {in} {out}\n' >"$tmp/bad.toml"
expect 2 "peers file that is not TOML" -- "$dtlab" oracle "$tmp/pts.xyz" --peers "$tmp/bad.toml"
has_err "bad.toml:3: not TOML: " "file:line of the TOML error"
printf '[[peers]]\nname = "x"\ncomand = "a {in} {out}"\n' >"$tmp/typo.toml"
expect 2 "TOML peer with an unknown field" -- "$dtlab" oracle "$tmp/pts.xyz" --peers "$tmp/typo.toml"
has_err "typo.toml:3: peer 1: unknown field 'comand' \(name, command, kind\)" "the misspelt key named"
printf '[[peers]]\nname = "x"\n\n[[peers]]\nname = "y"\ncommand = "prog {in}"\n' >"$tmp/noout.toml"
expect 2 "TOML peer without a command, then without {out}" -- "$dtlab" oracle "$tmp/pts.xyz" --peers "$tmp/noout.toml"
has_err "noout.toml:1: peer 1: needs command" "the entry's line"
printf '[[peers]]\nname = "y"\ncommand = "prog {in}"\n' >"$tmp/noout2.toml"
expect 2 "TOML peer without {out}" -- "$dtlab" oracle "$tmp/pts.xyz" --peers "$tmp/noout2.toml"
has_err "noout2.toml:3: peer 1: .*no \{out\}" "the command's line"
printf '[[peers]]\nname = "y"\ncommand = ["prog", 3]\n' >"$tmp/argv.toml"
expect 2 "TOML argv with a number" -- "$dtlab" oracle "$tmp/pts.xyz" --peers "$tmp/argv.toml"
has_err "argv.toml:3: peer 1: command must be a string or an array of strings" "the command's type"
printf 'peer = 1\n' >"$tmp/top.toml"
expect 2 "TOML without [[peers]]" -- "$dtlab" oracle "$tmp/pts.xyz" --peers "$tmp/top.toml"
has_err "top.toml:1: unknown key 'peer'" "the top-level key"
printf '{"peers": [{"name": "x", "command": "a {in} {out}", "timeout": 5}]}\n' >"$tmp/extra.json"
expect 2 "JSON peer with an unknown field" -- "$dtlab" oracle "$tmp/pts.xyz" --peers "$tmp/extra.json"
has_err "extra.json:0: peer 1: unknown field 'timeout'" "the JSON field named"
printf '{"peers": [{"name": "x", "command": "a {in} {out}"}, {"name": "y", "command": "a {in} {out}", "name": "z"}]}\n' >"$tmp/twice.json"
expect 2 "JSON peer naming a field twice" -- "$dtlab" oracle "$tmp/pts.xyz" --peers "$tmp/twice.json"
has_err "twice.json:0: peers\[1\]: duplicate field 'name'" "the repeated field named, not the last one kept"
printf '{"peers": [{"name": "x", "command": "a {in} \\"{out}"}]}\n' >"$tmp/quote.json"
expect 2 "JSON peer with an unterminated quote" -- "$dtlab" oracle "$tmp/pts.xyz" --peers "$tmp/quote.json"
has_err "quote.json:0: peer 1: unterminated quote" "the split error, file-located"

# Bad templates: exit 2, one line naming the problem.
expect 2 "no {in}" -- "$dtlab" oracle "$tmp/pts.xyz" --peer "p=prog {out}"
has_err "dtlab oracle: --peer: peer 'p': the command has no \{in\}" "missing {in} message"
expect 2 "no {out}" -- "$dtlab" oracle "$tmp/pts.xyz" --peer "p=prog {in}"
has_err "has no \{out\}" "missing {out} message"
expect 2 "unknown placeholder" -- "$dtlab" fuzz --target p --peer "p=prog {input} {out}" --out "$tmp/f0"
has_err "unknown placeholder '\{input\}'" "placeholder message"
expect 2 "no =" -- "$dtlab" oracle "$tmp/pts.xyz" --peer "prog {in} {out}"
expect 2 "unterminated quote" -- "$dtlab" oracle "$tmp/pts.xyz" --peer "p=prog '{in} {out}"
expect 2 "a built-in peer's name" -- "$dtlab" oracle "$tmp/pts.xyz" --peer "cgal=prog {in} {out}"
has_err "built-in peer" "name clash message"
expect 2 "unknown peer still refused" -- "$dtlab" fuzz --target nosuch --out "$tmp/f1"

# Misbehaving commands: each a verdict; dtlab's --json stays one object.
cat >"$tmp/chatty.sh" <<SH
#!/usr/bin/env bash
echo "hello from the peer on stdout"; echo '{"not": "dtlab"}'
"$dtlab" tetra "\$1" --out "\$2"
SH
printf '#!/usr/bin/env bash\nprintf "2 4 0\\n0 0 1 2 3\\n1 0 1 2 999\\n" >"$2.ele"\n' >"$tmp/range.sh"
printf '#!/usr/bin/env bash\necho "bananas" >"$2.ele"\n' >"$tmp/garbage.sh"
printf '#!/usr/bin/env bash\necho "cannot triangulate this" >&2; exit 5\n' >"$tmp/refuse.sh"
printf '#!/usr/bin/env bash\nkill -SEGV $$\n' >"$tmp/crash.sh"
printf '#!/usr/bin/env bash\nexit 0\n' >"$tmp/silent.sh"
printf '#!/usr/bin/env bash\nsleep 31.4159 &\nsleep 31.4159\n' >"$tmp/hang.sh"
chmod +x "$tmp"/*.sh
expect 0 "a peer that prints on stdout" -- "$dtlab" oracle "$tmp/pts.xyz" --against chatty --peer "chatty=$tmp/chatty.sh {in} {out}" --json
python3 -c 'import json,sys; j = json.load(open(sys.argv[1])); assert j["peers"]["chatty"]["verdict"] == "delaunay", j' "$tmp/out" \
  && pass=$((pass + 1)) || { echo "FAIL: --json not one object, or chatty not delaunay"; fails=$((fails + 1)); }
expect 0 "out-of-range ids" -- "$dtlab" oracle "$tmp/pts.xyz" --against range --peer "range=$tmp/range.sh {in} {out}"
has "^  range +invalid .*unreadable answer: out.ele:3: vertex index 999 out of range" "out-of-range verdict"
expect 0 "garbage .ele" -- "$dtlab" oracle "$tmp/pts.xyz" --against garbage --peer "garbage=$tmp/garbage.sh {in} {out}"
has "^  garbage +invalid .*unreadable answer: out.ele:1" "garbage verdict"
expect 3 "exit 5 without output" -- "$dtlab" oracle "$tmp/pts.xyz" --against refuse --peer "refuse=$tmp/refuse.sh {in} {out}"
has "^  refuse +refused .*cannot triangulate this" "refused with its message"
expect 3 "exit 0 without output" -- "$dtlab" oracle "$tmp/pts.xyz" --against silent --peer "silent=$tmp/silent.sh {in} {out}"
has "^  silent +refused .*wrote no \{out\}.ele" "no .ele"
expect 3 "a crash" -- "$dtlab" oracle "$tmp/pts.xyz" --against crash --peer "crash=$tmp/crash.sh {in} {out}"
has "^  crash +crashed .*signal 11" "crashed"
expect 3 "a program that does not exist" -- "$dtlab" oracle "$tmp/pts.xyz" --against gone --peer "gone=/nonexistent/prog {in} {out}"
has "^  gone +not-installed" "not-installed"
expect 3 "a peer that never exits" -- "$dtlab" oracle "$tmp/pts.xyz" --against hang --peer "hang=$tmp/hang.sh {in} {out}" --timeout 1
has "^  hang +hung" "hung"
sleep 0.2
if pgrep -f "sleep 31.4159" >/dev/null; then echo "FAIL: the hung peer's processes are still running"; fails=$((fails + 1)); else pass=$((pass + 1)); fi

# fuzz --against and --target with an external command.
expect 0 "fuzz --against a command peer" -- "$dtlab" fuzz --family uniform --cases 2 --against self --peer "self=$self" --out "$tmp/f2"
# A peer that is wrong on some inputs: it drops the last tet whenever there are 9 points or more.
cat >"$tmp/drop.sh" <<SH
#!/usr/bin/env bash
"$dtlab" tetra "\$1" --out "\$2.tmp" >/dev/null || exit 1
n=\$(head -1 "\$1" | cut -d' ' -f1)
if [ "\$n" -ge 9 ]; then
  t=\$(head -1 "\$2.tmp.ele" | cut -d' ' -f1)
  { echo "\$((t - 1)) 4 0"; sed -n "2,\${t}p" "\$2.tmp.ele"; } >"\$2.ele"
else
  cp "\$2.tmp.ele" "\$2.ele"
fi
SH
chmod +x "$tmp/drop.sh"
expect 1 "fuzz --target a wrong command peer" -- "$dtlab" fuzz --target drop --peer "drop=$tmp/drop.sh {in} {out}" \
  --family uniform --cases 1 --min-points 20 --points 20 --out "$tmp/f3"
has "drop case 0 on uniform|uniform case 0: (invalid|gap)" "the failure listed"
side=$(ls "$tmp/f3/corpus/"*.json 2>/dev/null | head -1)
python3 - "$side" <<'PY' && pass=$((pass + 1)) || { echo "FAIL: shrunk sidecar"; fails=$((fails + 1)); }
import json, sys
j = json.load(open(sys.argv[1]))
assert j["points"] == 9 and j["minimal"], j          # 1-minimal: 9 points, any 8 pass
assert "--peer 'drop=" in j["command"], j["command"]  # the replay defines the peer again
PY
node=$(ls "$tmp/f3/corpus/"*.node | head -1)
expect 0 "replaying the shrunk input" -- "$dtlab" oracle "$node" --against drop --peer "drop=$tmp/drop.sh {in} {out}"
has "^  drop +invalid" "still fails when replayed"

# experiment leaderboard: a --peer gets its own row.
expect 0 "leaderboard with a command peer" -- "$dtlab" experiment leaderboard --quick --peers cgal --peer "self=$self" \
  --family uniform,kettner_grid --cases 1 --no-meshes --speed-n 500 --out "$tmp/lb" --quiet
[ "$(grep -c '^self,' "$tmp/lb/leaderboard.csv")" -eq 2 ] && grep -q '^| `self` | command: ' "$tmp/lb/report.md" \
  && pass=$((pass + 1)) || { echo "FAIL: no row for the command peer"; fails=$((fails + 1)); }

echo "$pass passed, $fails failed"
[ "$fails" -eq 0 ]
