#!/usr/bin/env bash
# Adaptive grading of a scene with a covered mating roll grades on that
# scene: its passes solve the two-roll nip (TwoRollContact), not the nip
# against a rigid circle of the mating roll's radius.
#
# Usage: bash adaptive_grading_two_rolls.sh ROLLNIP PRM
#
# Scene: PRM (parameters/two_rolls.prm) with Mesh/Adaptive grading passes
# = 1, both rolls at Global refinements = 0, one nip (Contact/Values =
# 20 kN/m), no error estimate and no VTU files, to keep it small.
#
# Asserts: exit code 0, nothing on standard error; the screen before
# "Adaptive grading, pass 1" shows the two-roll outer iteration
# ("Two-roll contact"), which a solve against a rigid circle never prints;
# the real run after it solves the two-roll nip as well.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 2 ] || fail "usage: adaptive_grading_two_rolls.sh ROLLNIP PRM"
require_executable rollnip "$1"
rollnip="$(realpath "$1")"
prm="$(realpath "$2")"
start_test adaptive_grading_two_rolls

cp "$prm" scene.prm
cat >> scene.prm <<'PRM'

subsection Mesh
  set Adaptive grading passes = 1
  set Global refinements      = 0
end
subsection Mating roll
  subsection Mesh
    set Global refinements = 0
  end
end
subsection Contact
  set Values = 20
end
subsection Accuracy
  set Error estimate = false
end
subsection Output
  set Directory = output
  set Write VTU = false
end
PRM

rc=0
"$rollnip" scene.prm > stdout.txt 2> stderr.txt || rc=$?
[ "$rc" -eq 0 ] || { cat stderr.txt; fail "exit code $rc, expected 0"; }
pass "exit code 0"
[ ! -s stderr.txt ] || { cat stderr.txt; fail "standard error is not empty"; }
pass "nothing on standard error"

grep -q "^Adaptive grading, pass 1" stdout.txt ||
  fail "no 'Adaptive grading, pass 1' line on the screen"
grading="$(sed -n '1,/^Adaptive grading, pass 1/p' stdout.txt)"
run="$(sed -n '/^Adaptive grading, pass 1/,$p' stdout.txt)"
grep -q "^Two-roll contact" <<< "$grading" ||
  fail "the grading pass did not solve the two-roll nip (no 'Two-roll contact' line before 'Adaptive grading, pass 1')"
pass "the grading pass solved the two-roll nip: $(grep -c "^Two-roll contact" <<< "$grading") two-roll solve(s)"
grep -q "^Two-roll contact" <<< "$run" ||
  fail "the run after grading did not solve the two-roll nip"
pass "the graded run solved the two-roll nip"
[ -f output/contact.txt ] || fail "no output/contact.txt"
pass "output/contact.txt written"
