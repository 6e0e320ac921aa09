#!/usr/bin/env bash
# Long pressure expressions: muparser takes at most 20000 characters.
#  1. The parabolic pressure of parameters/parabolic_pressure.prm followed
#     by 2000 terms '+ 0 * theta' (about 24 kB, under 20000 characters
#     without blanks, which muparser ignores): valid, the same load line as
#     the short expression.
#  2. The same without blanks (24 kB) and 140000 terms (1.1 MB): refused
#     with one line under 400 characters that echoes the first 60
#     characters and gives muparser's reason and the limit.
#
# Usage: bash long_expression.sh ROLLNIP PRESSURE_PRM
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

scene_test_args long_expression PRESSURE_PRM "$@"

# with_expression FILE EXPRESSION: the scene with that pressure.
with_expression()
{
  cp "$scene" "$1"
  printf '\nsubsection Load\n  set Pressure function = %s\nend\n' "$2" >> "$1"
}
short='theta < theta0 ? p0 * (1 - (theta/theta0)^2) : 0'
with_expression short.prm "$short"
with_expression blanks.prm "($short)$(printf ' + 0 * theta%.0s' $(seq 1 2000))"
with_expression dense.prm "($short)$(printf '+0*theta%.0s' $(seq 1 3000))"
with_expression huge.prm "($short)$(printf '+0*theta%.0s' $(seq 1 140000))"

"$rollnip" --validate short.prm > short.txt
"$rollnip" --validate blanks.prm > blanks.txt 2> blanks.err ||
  fail "the 24 kB expression with blanks was refused: $(cat blanks.err)"
[ "$(grep '^Load: ' blanks.txt)" = "$(grep '^Load: ' short.txt)" ] ||
  fail "the long expression gives another load than the short one"
pass "$(wc -c < blanks.prm) bytes with blanks: valid, the load of the short expression"

for case in dense huge; do
  rc=0
  "$rollnip" --validate "$case.prm" > /dev/null 2> "$case.err" || rc=$?
  cat "$case.err"
  [ "$rc" -eq 1 ] || fail "$case: exit code $rc, expected 1"
  [ "$(wc -l < "$case.err")" -eq 1 ] || fail "$case: expected one line on standard error"
  [ "$(wc -c < "$case.err")" -lt 400 ] || fail "$case: the line has $(wc -c < "$case.err") characters"
  echoed="$(sed -n "s/^rollnip: error: Load\/Pressure function: cannot parse '\([^']*\)' .*/\1/p" "$case.err")"
  [ "${#echoed}" -eq 63 ] && [[ "$echoed" == "(theta < theta0 ? p0"*"..." ]] ||
    fail "$case: the expression is not echoed as its first 60 characters and '...'"
  grep -q "Expression too long.*at most 20000 characters" "$case.err" ||
    fail "$case: muparser's reason and the limit are not given"
  pass "$case ($(wc -c < "$case.prm") bytes): one line of $(wc -c < "$case.err") characters with muparser's reason"
done
