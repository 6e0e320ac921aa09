#!/usr/bin/env bash
# Bad input must be refused cleanly.
#
# Usage: bash expect_error.sh ROLLNIP PRM REGEX [FILE...]
#   ROLLNIP  the rollnip executable
#   PRM      the parameter file to pass (an absolute path, or a name that is
#            looked up in the working directory), or the word NONE to run
#            rollnip without any argument
#   REGEX    extended regular expression the error line must match; it
#            should name the parameter or file at fault
#   FILE...  files copied into the working directory first (meshes that PRM
#            names by a relative path)
#
# Runs rollnip in a fresh temporary directory and asserts: exit code exactly
# 1 (non-zero, and not a crash: a signal gives 128+n, an abort 134, an
# uncaught exception under MPI something else again), exactly one line on
# standard error, beginning with 'rollnip: error:' and matching REGEX.
# Then 'rollnip --validate PRM' must refuse it with the same line, except
# the inputs below that only the solve can find wrong.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -ge 3 ] || fail "usage: expect_error.sh ROLLNIP PRM REGEX [FILE...]"
rollnip="$1"
prm="$2"
regex="$3"
shift 3
require_executable rollnip "$rollnip"
if [ "$prm" != NONE ] && [ -e "$prm" ]; then
  prm="$(cd "$(dirname "$prm")" && pwd)/$(basename "$prm")"
fi
for f in "$@"; do
  [ -f "$f" ] || fail "data file '$f' does not exist"
done

start_test "expect_error-$(basename "$prm" .prm)"
for f in "$@"; do
  cp "$f" .
done

rc=0
if [ "$prm" = NONE ]; then
  echo "running: rollnip (no argument)"
  "$rollnip" > stdout.txt 2> stderr.txt || rc=$?
else
  echo "running: rollnip $prm"
  "$rollnip" "$prm" > stdout.txt 2> stderr.txt || rc=$?
fi

echo "--- standard error:"
cat stderr.txt
echo "---"

[ "$rc" -ne 0 ] || fail "rollnip accepted the input (exit code 0)"
if [ "$rc" -gt 128 ]; then
  fail "exit code $rc: rollnip was killed by signal $((rc - 128)) (a crash), expected exit code 1"
fi
[ "$rc" -eq 1 ] || fail "exit code $rc, expected 1"
pass "exit code 1"

n_lines="$(wc -l < stderr.txt)"
[ "$n_lines" -eq 1 ] ||
  fail "standard error has $n_lines lines, expected exactly one 'rollnip: error:' line"
pass "one line on standard error"

line="$(head -n 1 stderr.txt)"
[[ "$line" == "rollnip: error:"* ]] ||
  fail "the error line does not begin with 'rollnip: error:'"
pass "it begins with 'rollnip: error:'"

[[ "$line" =~ $regex ]] || fail "the error line does not match /$regex/"
pass "it matches /$regex/"

# Found only while solving, so --validate passes them: a face law table
# shorter than the approaches the face reaches, and a mating roll's sector
# narrower than the nip the load needs (both depend on the solution).
case "$(basename "$prm")" in
  NONE | face_law_too_short.prm | mating_roll_sector_load.prm)
    exit 0 ;;
esac
rc=0
"$rollnip" --validate "$prm" > validate_stdout.txt 2> validate_stderr.txt || rc=$?
[ "$rc" -eq 1 ] || { cat validate_stderr.txt; fail "--validate: exit code $rc, expected 1"; }
[ "$(cat validate_stderr.txt)" = "$line" ] ||
  { cat validate_stderr.txt; fail "--validate refuses it with another line than the run"; }
pass "--validate refuses it with the same line"
