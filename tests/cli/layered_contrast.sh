#!/usr/bin/env bash
# A layered cover with a stiffness contrast of 1e5: a 3 mm layer with
# G = 1e5 MPa on the core under 10.5 mm with G = 1 MPa
# (parameters/layered_cover.prm at 10 N/mm). Newton's round-off floor is
# that of the stiffest layer (with the surface layer's, every nip failed
# as "the cover cannot carry the first pressure guess"). The stiff layer
# is all but rigid: the nip agrees with one 10.5 mm layer on a rigid core
# of radius 50.2 mm, on a mesh of the same size, to 0.3 % in theta0 and
# u0.
#
# Usage: bash layered_contrast.sh ROLLNIP LAYERED_PRM
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

scene_test_args layered_contrast LAYERED_PRM "$@"

# run NAME MATERIAL_AND_GEOMETRY: the nip at 10 N/mm, output in NAME/.
run()
{
  cp "$scene" "$1.prm"
  cat >> "$1.prm" <<PRM
$2
subsection Contact
  set Values                     = 10
  set Compare with linear theory = false
end
subsection Accuracy
  set Error estimate = false
end
PRM
  quiet_output "$1" >> "$1.prm"
  run_named "$1"
}
run layered "subsection Material
  set C1 = 25000, 0.25
  set C2 = 25000, 0.25
end"
run rigid_core "subsection Geometry
  set Inner radius = 50.2
end
subsection Material
  set C1                = 0.25
  set C2                = 0.25
  set Layer thicknesses = 10.5
end"
pass "the layered cover with a contrast of 1e5 converges"
for q in theta0_deg u0_mm; do
  a="$(csv_value layered/nip_characteristic.csv "$q" 1)"
  b="$(csv_value rigid_core/nip_characteristic.csv "$q" 1)"
  awk -v a="$a" -v b="$b" 'BEGIN { d = a / b - 1; exit !((d < 0 ? -d : d) < 3e-3) }' ||
    fail "$q: $a with the stiff layer, $b on a rigid core"
  pass "$q: $a with the stiff layer, $b on a rigid core (within 0.3 %)"
done
