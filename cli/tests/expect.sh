# Shared by the CLI test scripts (sourced as `source expect.sh DTLAB`): a scratch folder
# removed on exit, pass/fail counters, and
#   expect CODE DESCRIPTION -- command...   runs the command with its output in $tmp/out
#                                           and $tmp/err; a failure when the exit differs
#                                           (EXPECT_TIMEOUT=S: each command gets S seconds)
#   says DESCRIPTION PATTERN                the last command's output matches PATTERN
#   never DESCRIPTION PATTERN               ... does not match PATTERN
#   ok DESCRIPTION CONDITION...             CONDITION (a command) succeeds
dtlab="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
pass=0
expect() {
  local want=$1 what=$2
  shift 3
  ${EXPECT_TIMEOUT:+timeout "$EXPECT_TIMEOUT"} "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  if [ "$got" -ne "$want" ]; then
    echo "FAIL: $what: exit $got, expected $want"; sed 's/^/  | /' "$tmp/out" "$tmp/err" | head -20; fails=$((fails + 1))
  else
    pass=$((pass + 1))
  fi
}
says() {
  if grep -qE -- "$2" "$tmp/out" "$tmp/err"; then pass=$((pass + 1)); else
    echo "FAIL: $1: no /$2/ in:"; sed 's/^/  | /' "$tmp/out" "$tmp/err" | head -8; fails=$((fails + 1)); fi
}
never() {
  if grep -qE -- "$2" "$tmp/out" "$tmp/err"; then
    echo "FAIL: $1: /$2/ in:"; sed 's/^/  | /' "$tmp/out" "$tmp/err" | head -8; fails=$((fails + 1)); else pass=$((pass + 1)); fi
}
ok() {
  local what=$1; shift
  if "$@"; then pass=$((pass + 1)); else echo "FAIL: $what"; fails=$((fails + 1)); fi
}
