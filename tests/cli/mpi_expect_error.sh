#!/usr/bin/env bash
# Bad input under 'mpiexec -np 2' must end every process with the one-line
# message, never hang and never crash.
#
# Usage: bash mpi_expect_error.sh ROLLNIP MPIEXEC PRM REGEX [FILE...]
#   as expect_error.sh, with MPIEXEC the MPI launcher
#
# Runs 'MPIEXEC -np 2 rollnip PRM' in a fresh temporary directory under a
# 60 s timeout and asserts: it ends in time, with a non-zero exit code that
# is not a signal's, and exactly one 'rollnip: error:' line on standard
# error matching REGEX (the launcher may add its own lines about the
# non-zero exit).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -ge 4 ] || fail "usage: mpi_expect_error.sh ROLLNIP MPIEXEC PRM REGEX [FILE...]"
rollnip="$1"
mpiexec="$2"
prm="$3"
regex="$4"
shift 4
require_executable rollnip "$rollnip"
require_executable "mpiexec (MPIEXEC_EXECUTABLE)" "$mpiexec"
[ -f "$prm" ] || fail "parameter file '$prm' not found"
prm="$(cd "$(dirname "$prm")" && pwd)/$(basename "$prm")"
start_test "mpi_expect_error-$(basename "$prm" .prm)"
for f in "$@"; do
  cp "$f" .
done

mpi_setup "$mpiexec"
limit=60
echo "running: $mpiexec ${mpi_flags[*]} -np 2 rollnip $prm (limit $limit s)"
rc=0
timeout --kill-after=10 "$limit" "$mpiexec" "${mpi_flags[@]}" -np 2 "$rollnip" "$prm" \
  > stdout.txt 2> stderr.txt || rc=$?
echo "--- standard error:"
cat stderr.txt
echo "---"
if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then
  fail "the run on 2 MPI processes did not end within $limit s (a hang)"
fi
[ "$rc" -ne 0 ] || fail "rollnip accepted the input (exit code 0)"
[ "$rc" -le 128 ] || fail "exit code $rc: killed by signal $((rc - 128)) (a crash)"
pass "ended with exit code $rc, not a signal"
n="$(grep -c '^rollnip: error:' stderr.txt || true)"
[ "$n" -eq 1 ] || fail "$n 'rollnip: error:' lines, expected one"
pass "one 'rollnip: error:' line"
line="$(grep '^rollnip: error:' stderr.txt)"
[[ "$line" =~ $regex ]] || fail "the error line does not match /$regex/"
pass "it matches /$regex/"
