#!/usr/bin/env bash
# One vocabulary, one error style, progress that can be silenced:
# - every subcommand's --help (walked from `dtlab --help` down) against one table of
#   shared option names, defaults and value names (shared_options.tsv) and of old
#   spellings kept as aliases (option_aliases.tsv); no "{false}" artefacts;
# - per subcommand, a bad input or bad usage gives `dtlab <command>: [file:line: ]reason`
#   on stderr, exit 2, and with --json {"error": {...}, "exit": 2} on stdout;
# - progress lines on stderr (DTLAB_PROGRESS_SECONDS=0: at every step), none with --quiet.
set -u
. "$(dirname "$0")/expect.sh"
here=$(cd "$(dirname "$0")" && pwd)

# Every command path, from the top-level help down ("mesh check", "experiment benchmark").
subcommands() {
  "$dtlab" "$@" --help | awk '/^Subcommands:/ { s = 1; next } s && /^  [a-z]/ { print $1; next } s && !/^   / { s = 0 }'
}
mkdir -p "$tmp/help"
paths=()
for top in $(subcommands); do
  subs=$(subcommands "$top")
  if [ -z "$subs" ]; then paths+=("$top"); else for s in $subs; do paths+=("$top $s"); done; fi
done
[ "${#paths[@]}" -ge 12 ] && pass=$((pass + 1)) || { echo "FAIL: found only ${#paths[@]} subcommands: ${paths[*]}"; fails=$((fails + 1)); }
for p in "${paths[@]}"; do
  # shellcheck disable=SC2086
  expect 0 "$p --help" -- "$dtlab" $p --help
  cp "$tmp/out" "$tmp/help/${p// /_}"
done
if grep -l '{false}\|{true}' "$tmp/help/"* >/dev/null; then
  echo "FAIL: {false} in the help of: $(grep -l '{false}\|{true}' "$tmp/help/"* | xargs -n1 basename)"; fails=$((fails + 1))
else pass=$((pass + 1)); fi

/usr/bin/python3 - "$tmp/help" "$here/shared_options.tsv" "$here/option_aliases.tsv" <<'PY' || fails=$((fails + 1))
import os, re, sys
helpdir, table, aliases = sys.argv[1:4]

def options(text):
    """{first name: (all names, value name, default or None)} of one --help text."""
    out = {}
    for line in text.splitlines():
        if not line.startswith("  -"):
            continue
        spec = re.split(r"\s{2,}", line.strip())[0]
        names, _, rest = spec.partition(" ")
        names = [n for n in names.split(",") if n.startswith("--")]
        if not names:
            continue
        value = re.split(r"[:= ]", rest)[0] if rest else "flag"
        default = None
        if "=" in rest:
            default = rest.rsplit("=", 1)[1].split()[0]
        out[names[0]] = (names, value or "flag", default)
    return out

helps = {f.replace("_", " "): options(open(os.path.join(helpdir, f)).read()) for f in os.listdir(helpdir)}
rows = [l.rstrip("\n").split("\t") for l in open(table) if l.strip() and not l.startswith("#")]
bad = []
allowed = {}
for opt, default, value, commands in rows:
    allowed.setdefault(opt, set()).add(default)
    for c in commands.split(";"):
        if c not in helps:
            bad.append(f"table names an unknown command '{c}'")
            continue
        got = helps[c].get(opt)
        if not got:
            bad.append(f"{c}: no {opt}")
            continue
        names, v, d = got
        if default == "flag":
            if v != "flag":
                bad.append(f"{c}: {opt} should be a flag, shows value {v}")
        elif default != "-" and d != default:
            bad.append(f"{c}: {opt} default {d!r}, the table says {default!r}")
        if value != "-" and v != value:
            bad.append(f"{c}: {opt} value {v!r}, the table says {value!r}")
# Wherever else a table option appears, its default is one of the table's.
for c, opts in helps.items():
    for opt, (names, v, d) in opts.items():
        if opt in allowed and "-" not in allowed[opt] and "flag" not in allowed[opt] and d not in allowed[opt]:
            bad.append(f"{c}: {opt} default {d!r}, the table allows {sorted(allowed[opt])}")
for l in open(aliases):
    if not l.strip() or l.startswith("#"):
        continue
    alias, canonical, command = l.rstrip("\n").split("\t")
    opts = helps.get(command, {})
    if " " in canonical:  # a flag standing for an option's value: its help names the canonical form
        if alias not in opts:
            bad.append(f"{command}: no alias {alias}")
        elif canonical not in open(os.path.join(helpdir, command.replace(" ", "_"))).read():
            bad.append(f"{command}: the help of {alias} does not name {canonical}")
    elif canonical not in opts or alias not in opts[canonical][0]:
        bad.append(f"{command}: {alias} is not an alias of {canonical}")
for b in bad:
    print("FAIL:", b)
print(f"shared options: {len(rows)} rows, {len(helps)} commands, {len(bad)} problems")
sys.exit(1 if bad else 0)
PY

# Errors: one line `dtlab <command>: [file:line: ]reason`, exit 2, and a JSON object with --json.
printf '5 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 one\n4 1 1 1\n' > "$tmp/bad.node"
printf '1 4 0\n0 0 1 2 3\n' > "$tmp/bad.ele"
printf 'OFF\n3 1 0\n0 0 0\n1 0 x\n0 1 0\n3 0 1 2\n' > "$tmp/bad.off"
json_error() {  # json_error COMMAND FILE LINE: the last stdout is the JSON error object
  /usr/bin/python3 - "$tmp/out" "$1" "$2" "$3" <<'PY'
import json, sys
path, command, file, line = sys.argv[1:5]
j = json.load(open(path))
e = j["error"]
assert j["exit"] == 2, j
assert e["command"] == command, e
assert (e["file"] or "") == file, e
assert (e["line"] or 0) == int(line), e
assert e["reason"], e
PY
}
file_error() {  # file_error COMMAND FILE LINE -- args...: the error of a bad input file
  local command=$1 file=$2 line=$3
  shift 4
  expect 2 "$command on a bad file" -- "$dtlab" "$@"
  if grep -qE "^dtlab $command: $file:$line: .+" "$tmp/err" && [ "$(wc -l < "$tmp/err")" -eq 1 ]; then pass=$((pass + 1)); else
    echo "FAIL: $command error line: $(cat "$tmp/err")"; fails=$((fails + 1)); fi
  expect 2 "$command --json on a bad file" -- "$dtlab" "$@" --json
  if json_error "$command" "$file" "$line"; then pass=$((pass + 1)); else
    echo "FAIL: $command --json error object:"; sed 's/^/  | /' "$tmp/out"; fails=$((fails + 1)); fi
}
usage_error() {  # usage_error COMMAND -- args...: bad usage, no file
  local command=$1
  shift 2
  expect 2 "$command: bad usage" -- "$dtlab" "$@"
  if grep -qE "^dtlab $command: .+" "$tmp/err" && [ "$(wc -l < "$tmp/err")" -eq 1 ]; then pass=$((pass + 1)); else
    echo "FAIL: $command usage error line: $(cat "$tmp/err")"; fails=$((fails + 1)); fi
  expect 2 "$command --json: bad usage" -- "$dtlab" "$@" --json
  if json_error "$command" "" 0; then pass=$((pass + 1)); else
    echo "FAIL: $command --json usage error object:"; sed 's/^/  | /' "$tmp/out"; fails=$((fails + 1)); fi
}
file_error tetra "$tmp/bad.node" 5 -- tetra "$tmp/bad.node"
file_error check "$tmp/bad.node" 5 -- check "$tmp/bad"
file_error oracle "$tmp/bad.node" 5 -- oracle "$tmp/bad.node" --against cgal
file_error voronoi "$tmp/bad.node" 5 -- voronoi "$tmp/bad.node"
file_error fuzz "$tmp/bad.node" 5 -- fuzz --replay "$tmp/bad.node"
# A corpus entry is replayed with its sidecar's --order and --threads (printed after the
# file, in the JSON line too); a count out of range is refused, naming the sidecar and line.
mkdir -p "$tmp/rt"
printf '5 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 0.3 0.3 0.3\n' > "$tmp/rt/e.node"
printf '{\n  "outcome": "valid",\n  "order": "input",\n  "threads": 2\n}\n' > "$tmp/rt/e.json"
expect 0 "fuzz --replay of a threaded entry" -- "$dtlab" fuzz --replay "$tmp/rt/e.node"
says "the replay names the sidecar's settings" "^ok .* $tmp/rt/e.node --order input --threads 2 \(recorded: valid\)$"
expect 0 "fuzz --replay --threads 1 --order brio" -- "$dtlab" fuzz --replay "$tmp/rt/e.node" --threads 1 --order brio --json
ok "given, --threads and --order override the sidecar" /usr/bin/python3 -c "
import json, sys; r = json.load(open(sys.argv[1]))['results'][0]
assert (r['threads'], r['order'], r['parallel_passes']) == (1, 'brio', 0), r" "$tmp/out"
printf '{\n  "outcome": "valid"\n}\n' > "$tmp/rt/e.json"
expect 0 "fuzz --replay of an entry from before threads were kept" -- "$dtlab" fuzz --replay "$tmp/rt/e.node" --json
ok "an old sidecar replays serially with brio" /usr/bin/python3 -c "
import json, sys; r = json.load(open(sys.argv[1]))['results'][0]
assert (r['threads'], r['order'], r['outcome']) == (1, 'brio', 'valid'), r" "$tmp/out"
printf '{\n  "outcome": "valid",\n  "threads": 0\n}\n' > "$tmp/rt/e.json"
file_error fuzz "$tmp/rt/e.json" 3 -- fuzz --replay "$tmp/rt/e.node"
# The oracles an entry was compared with ("against") are run again; --against overrides; a
# name no oracle has, or an "against" that is no list, is the sidecar's error with its line.
printf '{\n  "outcome": "oracle-serial",\n  "threads": 2,\n  "against": ["serial"]\n}\n' > "$tmp/rt/e.json"
expect 0 "fuzz --replay of an entry compared with the serial build" -- "$dtlab" fuzz --replay "$tmp/rt/e.node"
says "the replay names the oracles it ran" "^ok .* --threads 2 --against serial \(recorded: oracle-serial\)$"
expect 0 "fuzz --replay --against none" -- "$dtlab" fuzz --replay "$tmp/rt/e.node" --against none --json
ok "--against none: the build alone" /usr/bin/python3 -c "
import json, sys; r = json.load(open(sys.argv[1]))['results'][0]
assert (r['against'], r['outcome']) == ([], 'valid'), r" "$tmp/out"
usage_error fuzz -- fuzz --replay "$tmp/rt/e.node" --against nosuchpeer
printf '{\n  "outcome": "valid",\n  "against": ["nosuchpeer"]\n}\n' > "$tmp/rt/e.json"
file_error fuzz "$tmp/rt/e.json" 3 -- fuzz --replay "$tmp/rt/e.node"
printf '{\n  "outcome": "valid",\n\n  "against": "cgal"\n}\n' > "$tmp/rt/e.json"
file_error fuzz "$tmp/rt/e.json" 4 -- fuzz --replay "$tmp/rt/e.node"
file_error sample "$tmp/bad.off" 4 -- sample "$tmp/bad.off" --out "$tmp/s.xyz"
file_error fracture "$tmp/bad.off" 4 -- fracture "$tmp/bad.off" --out "$tmp/f"
file_error "mesh check" "$tmp/bad.off" 4 -- mesh check "$tmp/bad.off"
file_error "mesh repair" "$tmp/bad.off" 4 -- mesh repair "$tmp/bad.off"
for p in "${paths[@]}"; do
  # shellcheck disable=SC2086
  usage_error "$p" -- $p --no-such-option
done
usage_error fuzz -- fuzz --family uniform --shard 3/2 --out "$tmp/fz"
usage_error fracture -- fracture builtin --pieces 2 --sampler surface
expect 2 "fracture without an output" -- "$dtlab" fracture builtin --pieces 2
grep -qx "dtlab fracture: nothing to write: give --out DIR (or --json, --png FILE)" "$tmp/err" && pass=$((pass + 1)) ||
  { echo "FAIL: fracture without an output: $(cat "$tmp/err")"; fails=$((fails + 1)); }
usage_error bench -- bench --tools nosuchtool
usage_error tetra -- tetra "$tmp/bad.node" --boundary bigtet:x
usage_error "experiment benchmark" -- experiment benchmark --runs 0 --out "$tmp/eb"

# Progress: a line per step with DTLAB_PROGRESS_SECONDS=0 (stderr not a terminal here), none with --quiet.
printf '0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n0.5 0.2 0.7\n' > "$tmp/ok.xyz"
progress() {  # progress DESCRIPTION PATTERN -- args...
  local what=$1 pattern=$2
  shift 3
  DTLAB_PROGRESS_SECONDS=0 "$dtlab" "$@" >"$tmp/out" 2>"$tmp/err"
  if grep -qE -- "$pattern" "$tmp/err"; then pass=$((pass + 1)); else
    echo "FAIL: $what: no /$pattern/ on stderr"; sed 's/^/  | /' "$tmp/err" | head -5; fails=$((fails + 1)); fi
  DTLAB_PROGRESS_SECONDS=0 "$dtlab" "$@" --quiet >"$tmp/out" 2>"$tmp/err"
  if grep -qE -- "$pattern" "$tmp/err"; then echo "FAIL: $what: progress despite --quiet"; fails=$((fails + 1)); else pass=$((pass + 1)); fi
}
progress "fuzz campaign" "^dtlab fuzz: cases 2/2 \(100%\), 0 failing; .* so far, done" -- \
  fuzz --family uniform --cases 2 --no-shrink --out "$tmp/pf"
progress "fuzz --target" "^dtlab fuzz: cases 2/2" -- fuzz --target dtlab:exact --family uniform --cases 2 --no-shrink --out "$tmp/pt"
progress "oracle peers" "^dtlab oracle: peers 0/2 \(0%\), running cgal" -- oracle "$tmp/ok.xyz" --against cgal,dtlab:exact
progress "bench runs" "^dtlab bench: runs 1/2 \(50%\).*ETA" -- bench --sizes 100 --tools dtlab --runs 2
progress "fracture stages" "^dtlab fracture: fracturing builtin at 2 winding sites" -- fracture builtin --pieces 2 --out "$tmp/pfr"
progress "fracture booleans" "^dtlab fracture: booleans 2/2 \(100%\)" -- fracture builtin --pieces 2 --out "$tmp/pfr"

echo "$pass passed, $fails failed"
[ "$fails" -eq 0 ]
