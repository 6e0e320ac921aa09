#!/usr/bin/env bash
# The two-roll nip at a given theta0 is unique to the control tolerance:
# the load-controlled nips of parameters/two_rolls.prm (both rolls at
# Global refinements 1; 20 and 60 N/mm, Control tolerance 1e-6), solved
# again in nip-angle mode at the theta0 they found (with the conformity
# tolerance load control used, 0.1 x Control tolerance), give the target
# P to 5 x Control tolerance (before, the mating roll's mesh was refitted
# only to 1e-3 of its angle, and P came back 5e-4 off).
#
# Usage: bash two_roll_reproducible.sh ROLLNIP TWO_ROLLS_PRM
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

scene_test_args two_roll_reproducible TWO_ROLLS_PRM "$@"

# run NAME CONTACT_ENTRIES: the scene on smaller meshes, output in NAME/.
run()
{
  cp "$scene" "$1.prm"
  cat >> "$1.prm" <<PRM
subsection Mesh
  set Global refinements = 1
end
subsection Mating roll
  subsection Mesh
    set Global refinements = 1
  end
end
subsection Contact
$2
  set Control tolerance          = 1e-6
  set Compare with linear theory = false
end
subsection Accuracy
  set Error estimate = false
end
PRM
  quiet_output "$1" >> "$1.prm"
  run_named "$1"
}
targets=(20 60)
run load "  set Mode = load
  set Values = 20, 60"
angles="$(csv_value load/nip_characteristic.csv theta0_deg 1), $(csv_value load/nip_characteristic.csv theta0_deg 2)"
run angle "  set Mode = nip angle
  set Values = $angles
  set Conformity tolerance = 1e-7"
for n in 1 2; do
  target="${targets[$((n - 1))]}"
  p="$(csv_value angle/nip_characteristic.csv P_N_per_mm "$n")"
  theta="$(csv_value angle/nip_characteristic.csv theta0_deg "$n")"
  awk -v p="$p" -v t="$target" 'BEGIN { d = p / t - 1; exit !((d < 0 ? -d : d) < 5e-6) }' ||
    fail "theta0 = $theta deg: P = $p N/mm in nip-angle mode, target $target N/mm"
  pass "theta0 = $theta deg: P = $p N/mm in nip-angle mode, target $target N/mm (within 5e-6)"
done
