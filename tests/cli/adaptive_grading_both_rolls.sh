#!/usr/bin/env bash
# Adaptive grading of a scene with a covered mating roll grades on that
# scene: its passes solve the two-roll nip (TwoRollContact), not the nip
# against a rigid circle of the mating roll's radius. It re-cuts the mating
# roll's cells too when its own Mating roll/Mesh/Adaptive grading passes
# asks for it: from its solved state in the two-roll nip, in the same
# passes as the first roll's.
#
# Usage: bash adaptive_grading_both_rolls.sh ROLLNIP PRM
#
# Scene: PRM (parameters/two_rolls.prm) with one grading pass for each
# roll, both at Global refinements = 0 (18 coarse cells over 90 deg, the
# widest 8 times the narrowest: 1.46 deg at the line of centres before
# grading), one nip (20 kN/m), no error estimate and no VTU files.
#
# Asserts: exit code 0, nothing on standard error; the screen before
# "Adaptive grading, pass 1" shows the two-roll outer iteration ("Two-roll
# contact"), which a solve against a rigid circle never prints, and so does
# the real run after it; one "Adaptive grading, pass 1" line for each roll; the mating roll's first coarse cell after
# grading is narrower than half its contact zone (asin(b / R_mate), b the
# half-chord of nip_characteristic.csv) and differs from the ungraded
# 1.46 deg; the real run used those cells: the first surface node of the
# mating roll off the line of centres (mating_roll/outer_surface.csv) lies
# at the printed width; both rolls carry the same P within 1e-3.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 2 ] || fail "usage: adaptive_grading_both_rolls.sh ROLLNIP PRM"
require_executable rollnip "$1"
rollnip="$(realpath "$1")"
prm="$(realpath "$2")"
start_test adaptive_grading_both_rolls

cp "$prm" scene.prm
cat >> scene.prm <<'PRM'

subsection Mesh
  set Adaptive grading passes = 1
  set Global refinements      = 0
end
subsection Mating roll
  subsection Mesh
    set Adaptive grading passes = 1
    set Global refinements      = 0
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

grep "^Adaptive grading" stdout.txt
grading="$(sed -n '1,/^Adaptive grading, pass 1/p' stdout.txt)"
run="$(sed -n '/^Adaptive grading, pass 1/,$p' stdout.txt)"
grep -q "^Two-roll contact" <<< "$grading" ||
  fail "the grading pass did not solve the two-roll nip (no 'Two-roll contact' line before 'Adaptive grading, pass 1')"
pass "the grading pass solved the two-roll nip: $(grep -c "^Two-roll contact" <<< "$grading") two-roll solve(s)"
grep -q "^Two-roll contact" <<< "$run" ||
  fail "the run after grading did not solve the two-roll nip"
pass "the graded run solved the two-roll nip"
grep -q "^Adaptive grading, pass 1: coarse cells" stdout.txt ||
  fail "the first roll was not graded"
line="$(grep "^Adaptive grading, pass 1 (mating roll): coarse cells from" stdout.txt)" ||
  fail "the mating roll was not graded"
first="$(sed -E 's/.*coarse cells from ([0-9.e+-]+) deg.*/\1/' <<< "$line")"
pass "the mating roll was graded: first coarse cell $first deg"

b="$(csv_value output/nip_characteristic.csv half_chord_mm 1)"
R_mate=200
zone="$(awk -v b="$b" -v R="$R_mate" 'BEGIN { x = b / R; print atan2(x, sqrt(1 - x * x)) * 180 / 3.14159265358979 }')"
check_less "first mating cell [deg]" "$first" "$(awk -v z="$zone" 'BEGIN { print z / 2 }')"
if awk -v f="$first" 'BEGIN { exit !((f - 1.4566) ^ 2 < 1e-4) }'; then
  fail "the mating roll's first cell ($first deg) is the ungraded one (1.4566 deg)"
fi
pass "it differs from the ungraded 1.4566 deg"

surface=output/mating_roll/outer_surface.csv
[ -f "$surface" ] || fail "no $surface"
theta1="$(csv_value "$surface" theta_deg 2)"
check_rel_close "first mating surface node off the line of centres [deg]" "$theta1" "$first" 5e-3

P="$(summary_value output/contact.txt nip_load_P_N_per_mm)"
P_mate="$(summary_value output/contact.txt mating_roll_nip_load_P_N_per_mm)"
# The mating roll is not nip-fitted once graded: its contact edge falls
# between its nodes, which leaves up to 0.07 % between the two P
# (doc/two_rolls.md, Verification).
check_rel_close "P of the mating roll [N/mm]" "$P_mate" "$P" 1e-3
