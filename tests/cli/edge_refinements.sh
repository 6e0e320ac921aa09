#!/usr/bin/env bash
# Mesh/Edge refinements: with theta0 prescribed, the cells at the contact
# edge set the first-order error of P, and each halving of them halves it.
# The run-30 scene (parameters/batra1980.prm) at theta0 = 8 deg, Q2-P1 at
# level 0, against the reference at that theta0 from the other element
# family: Q1-P0 at levels 3 to 5 extrapolated at orders 1 and 2, P =
# 10.5761461 N/mm (Q2-P1 at levels 2 to 4 extrapolated the same way
# matches it to 8.7e-6; benchmarks/nip_angle_reference.py). Measured: P
# off by -1.36e-2 without edge refinements, -1.72e-3 with 3 (7.9 times
# less; 6.5e-3, 3.3e-3 with 1, 2).
#
# Usage: bash edge_refinements.sh ROLLNIP BASE_PRM
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 2 ] || fail "usage: edge_refinements.sh ROLLNIP BASE_PRM"
rollnip="$1"
base="$2"
require_executable rollnip "$rollnip"
start_test edge_refinements

# run NAME K [ESTIMATE]: Q2-P1 at level 0 with K edge refinements, into
# NAME/; with ESTIMATE = true also its error estimate (the companion at
# level 1 starts from the level-0 nip carried over the nested meshes).
run()
{
  cat "$base" - > "$1.prm" <<PRM
subsection Mesh
  set Global refinements = 0
  set Edge refinements   = $2
end
subsection Discretization
  set Element = Q2-P1
end
subsection Contact
  set Values = 8
  set Compare with linear theory = false
end
PRM
  if [ "${3:-false}" = true ]; then
    quiet_output "$1" >> "$1.prm"
    run_named "$1"
  else
    run_quiet_scene "$1"
  fi
}

run plain 0
run edge3 3 true
P0=$(csv_value plain/nip_characteristic.csv P_N_per_mm 1)
P3=$(csv_value edge3/nip_characteristic.csv P_N_per_mm 1)
e0=$(awk -v p="$P0" 'BEGIN { e = p / 10.5761461 - 1; print e < 0 ? -e : e }')
e3=$(awk -v p="$P3" 'BEGIN { e = p / 10.5761461 - 1; print e < 0 ? -e : e }')
check_rel_close "P without edge refinements (1.36e-2 off)" "$P0" 10.5761461 1.6e-2
check_rel_close "P with 3 edge refinements (1.72e-3 off)" "$P3" 10.5761461 2e-3
# Three halvings: the first-order error falls 8 times (measured 7.9).
ratio=$(awk -v a="$e0" -v b="$e3" 'BEGIN { print a / b }')
check_less "error ratio, 0 over 3 edge refinements, above 6" 6 "$ratio"
check_less "error ratio, 0 over 3 edge refinements, below 10" "$ratio" 10
# Its error estimate (against level 1, order 1) exists and is finite.
est=$(csv_value edge3/nip_characteristic.csv P_err_N_per_mm 1)
check_less "estimated error of P with 3 edge refinements [N/mm], positive" 0 "$est"
check_less "estimated error of P with 3 edge refinements [N/mm], below 1 %" "$est" 0.106
# The edge cells are the only change: theta0 stays a vertex, and the mesh
# grows by the refined cells only.
d0=$(summary_value plain/summary.txt dofs)
d3=$(summary_value edge3/summary.txt dofs)
check_less "DoFs added by 3 edge refinements" "$((d3 - d0))" 400
