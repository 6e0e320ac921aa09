#!/usr/bin/env bash
# At mesh level 1 and above the error estimate's coarser companion solves
# each nip first and the run starts from its nip (doc/accuracy.md, "Error
# estimates"). The run-30 scene (BASE_PRM) at level 1, under nip-angle
# control (theta0 = 4, 8, 12 deg) and load control (P = 2, 10, 40 N/mm),
# each with Accuracy/Error estimate = true and false:
#  - the numbers do not depend on where the run started: theta0, P, u0, b
#    and the peak pressure agree within 3e-6 relative (6.1e-7 measured;
#    the contact iteration stops at a conformity of 1e-6 and the control
#    at 1e-6 relative, so each answer moves within about that);
#  - the run started from the companion's nips takes fewer contact
#    iterations (the rows the run prints: 8 against 10 under nip-angle
#    control and 19 against 27 under load control, measured).
#
# Usage: bash companion_first.sh ROLLNIP BASE_PRM
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 2 ] || fail "usage: companion_first.sh ROLLNIP BASE_PRM"
rollnip="$1"
base="$2"
require_executable rollnip "$rollnip"
[ -f "$base" ] || fail "parameter file '$base' not found"
start_test companion_first

# run NAME MODE VALUES ESTIMATE: NAME.prm at level 1, run into NAME/.
run()
{
  cp "$base" "$1.prm"
  cat >> "$1.prm" <<PRM
subsection Mesh
  set Global refinements = 1
end
subsection Contact
  set Mode = $2
  set Values = $3
  set Compare with linear theory = false
end
subsection Accuracy
  set Error estimate = $4
end
PRM
  quiet_output "$1" >> "$1.prm"
  run_named "$1"
}

# contact_rows NAME: the contact iterations NAME printed (one row each).
contact_rows()
{
  grep -cE '^ +[0-9]+ +[0-9.]+e[-+][0-9]+ ' "$1.txt"
}

for mode in "nip angle" load; do
  if [ "$mode" = load ]; then values="2, 10, 40"; else values="4, 8, 12"; fi
  name=${mode// /_}
  run "${name}_first" "$mode" "$values" true
  run "${name}_alone" "$mode" "$values" false
  for nip in 1 2 3; do
    for column in theta0_deg P_N_per_mm u0_mm half_chord_mm peak_pressure_MPa; do
      check_rel_close "$mode, nip $nip: $column with the companion first" \
        "$(csv_value "${name}_first/nip_characteristic.csv" "$column" "$nip")" \
        "$(csv_value "${name}_alone/nip_characteristic.csv" "$column" "$nip")" \
        3e-6
    done
  done
  check_less "$mode: contact iterations of the run started from the companion's nips" \
    "$(contact_rows "${name}_first")" "$(contact_rows "${name}_alone")"
done

