#!/usr/bin/env bash
# A rigid core bent along an elastic core's own deflection carries the
# elastic core's line load, the way a user makes it: the elastic run's
# core_deflection_along_axis.csv turned into a Core deflection expression
# by scripts/core_deflection_expression.py (the piecewise linear line
# through v at the cover's node planes).
#
# Usage: bash elastic_core_bent_twin.sh ROLLNIP PRM SCRIPT
#   PRM     parameters/elastic_core_3d.prm (level 0, 16 layers)
#   SCRIPT  scripts/core_deflection_expression.py
#
# Checks: q(z) of line_load_along_axis.csv of the two runs agrees within
# 0.5 % of the elastic q(0) at every plane (the slice's discretisation
# error at level 0 is 0.2-0.5 %, doc/three_d.md stage 1), while the
# elastic core's own q(0) is over 25 % below that of a straight rigid
# core (what the bending is worth; the twin must not be the straight
# core).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 3 ] || fail "usage: elastic_core_bent_twin.sh ROLLNIP PRM SCRIPT"
rollnip="$(realpath "$1")"
scene="$(realpath "$2")"
script="$(realpath "$3")"
require_executable rollnip "$rollnip"
[ -f "$script" ] || fail "script '$script' not found"
start_test elastic_core_bent_twin

cp "$scene" elastic.prm
quiet_output out_elastic >> elastic.prm
run_named elastic
pass "the elastic core ran"
L="$(summary_value out_elastic/summary.txt slice_thickness_mm)"
expression="$(python3 "$script" out_elastic/core_deflection_along_axis.csv --up-to "$L")" ||
  fail "core_deflection_expression.py failed"
pass "core_deflection_expression.py made the bending line up to z = $L mm"

for run in bent straight; do
  cp "$scene" "$run.prm"
  {
    printf '\nsubsection Three d\n  set Core = rigid\n'
    [ "$run" = bent ] && printf '  set Core deflection = %s\n' "$expression"
    printf 'end\n'
    quiet_output "out_$run"
  } >> "$run.prm"
  run_named "$run"
done
pass "the rigid core ran bent along that line and straight"

q0="$(csv_value out_elastic/line_load_along_axis.csv line_load_N_per_mm 1)"
worst="$(paste -d, out_elastic/line_load_along_axis.csv out_bent/line_load_along_axis.csv |
  awk -F, 'NR > 1 { if ($1 != $3) bad = 1; d = $2 - $4; d = d < 0 ? -d : d; if (d > m) m = d }
           END { if (bad) print "planes-differ"; else print m + 0 }')"
[ "$worst" != planes-differ ] || fail "the two runs' node planes differ"
check_less "largest |q_elastic - q_bent| over the planes [N/mm] (q(0) = $q0)" \
  "$worst" "$(awk -v q="$q0" 'BEGIN { print 0.005 * q }')"
q0_straight="$(csv_value out_straight/line_load_along_axis.csv line_load_N_per_mm 1)"
check_less "elastic q(0) over the straight rigid core's ($q0_straight N/mm)" \
  "$(awk -v a="$q0" -v b="$q0_straight" 'BEGIN { print a / b }')" 0.75
