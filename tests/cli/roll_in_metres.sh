#!/usr/bin/env bash
# A roll typed in metres (parameters/engineering_nip.prm with Roll diameter
# = 0.25 and Cover thickness = 0.0135) is warned about before the mesh is
# built, and its load, which the 0.25 mm roll cannot carry, is refused from
# the first guess on mesh level 0 rather than after minutes of failing
# contact solves on the fine mesh.
#
# Usage: bash roll_in_metres.sh ROLLNIP ENGINEERING_PRM
#
# Asserts: exit code 1; standard error is exactly two lines, the warning
# naming Geometry/Roll diameter = 0.25 mm and a unit mistake, then the
# error refusing P = 20 N/mm as out of reach from mesh level 0; the fine
# mesh ran no contact solve (no "Outer iteration" line on the screen).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 2 ] || fail "usage: roll_in_metres.sh ROLLNIP ENGINEERING_PRM"
require_executable rollnip "$1"
rollnip="$(realpath "$1")"
prm="$(realpath "$2")"
start_test roll_in_metres

sed -e 's/set Roll diameter .*/set Roll diameter = 0.25/' \
    -e 's/set Cover thickness .*/set Cover thickness = 0.0135/' \
    -e 's/set Values .*/set Values = 20/' "$prm" > metres.prm
cat >> metres.prm <<'PRM'
subsection Output
  set Directory = output
  set Write VTU = false
end
PRM
grep -q "Roll diameter = 0.25" metres.prm || fail "could not edit $prm"

rc=0
"$rollnip" metres.prm > stdout.txt 2> stderr.txt || rc=$?
echo "--- standard error:"
cat stderr.txt
echo "---"
[ "$rc" -eq 1 ] || fail "exit code $rc, expected 1"
pass "exit code 1"
[ "$(wc -l < stderr.txt)" -eq 2 ] || fail "expected two lines on standard error"
warning="rollnip: warning: Geometry/Roll diameter = 0.25 mm is outside 5 mm to 5 m, the range of rolls (a unit mistake? lengths are in mm)"
[ "$(sed -n 1p stderr.txt)" = "$warning" ] ||
  fail "the first line is not the warning: $warning"
pass "the first line is the unit warning"
regex="^rollnip: error: contact: the target P = 20 N/mm is out of reach: on mesh level 0 the largest P reached is .* N/mm at theta0 = .* deg before the search stopped, less than 50 % of the target"
[[ "$(sed -n 2p stderr.txt)" =~ $regex ]] ||
  fail "the second line does not match /$regex/"
pass "the second line refuses the target from mesh level 0"
! grep -q "^Outer iteration" stdout.txt ||
  fail "the fine mesh ran contact solves ('Outer iteration' on the screen)"
pass "no contact solve on the fine mesh"
