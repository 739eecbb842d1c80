# Shared by the CLI test scripts (sourced): a scratch folder removed on exit, pass/fail
# counters, and `expect CODE DESCRIPTION -- command...`, which runs the command with
# its output in $tmp/out and $tmp/err and counts a failure when the exit code differs.
dtlab="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
pass=0
expect() {
  local want=$1 what=$2
  shift 3
  "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  if [ "$got" -ne "$want" ]; then
    echo "FAIL: $what: exit $got, expected $want"; sed 's/^/  | /' "$tmp/out" "$tmp/err" | head -20; fails=$((fails + 1))
  else
    pass=$((pass + 1))
  fi
}
