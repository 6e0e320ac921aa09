#!/usr/bin/env bash
# A gmsh mesh from meshes/quarter_roll.geo under a uniform pressure.
#
# Usage: bash gmsh_hydrostatic.sh ROLLNIP GMSH GEO
#   GEO  meshes/quarter_roll.geo
#
# Meshes GEO with gmsh now (so the .geo file and rollnip's gmsh reader are
# tested together), then loads the cover with a uniform follower pressure
# p0 = 0.3 MPa on the outer arc (id 1), the inner arc (id 0) fixed and both
# straight edges (ids 2, 3) symmetry lines. The exact solution is u = 0 and
# sigma = -p0 I everywhere, and it is also the exact discrete solution: a
# constant stress is in equilibrium with the pressure on any polygonal
# boundary, and u = 0 satisfies J = 1 in every cell. So the checks are at
# round-off level:
#   |u_r(R0, 0)| < 1e-9 mm,
#   sigma_rr_min = sigma_rr_max = -p0 to 1e-8 MPa,
#   sigma_rtheta_max_abs < 1e-8 MPa,
#   nip_load_P = 2 p0 R0 to relative 1e-8.
# On P: the resultant of a uniform pressure on a curve is p0 times the
# chord rotated by 90 degrees, x-component = p0 * (y_end - y_start), whatever
# the shape in between. The outer boundary of the mesh is a polygon whose
# vertices lie on the circle, from (R0, 0) to (0, R0), so its x-resultant
# is p0 R0 exactly and the polygonal approximation of the arc (an O(h^2)
# error for most quantities) does not enter. The tolerance 1e-8 is set by
# summary.txt, which prints 8 significant digits.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 3 ] || fail "usage: gmsh_hydrostatic.sh ROLLNIP GMSH GEO"
rollnip="$1"
gmsh="$2"
geo="$3"
require_executable rollnip "$rollnip"
require_executable "gmsh (needed to mesh $geo)" "$gmsh"
[ -f "$geo" ] || fail "geometry file '$geo' not found"
start_test gmsh_hydrostatic

R1=47.2
R0=60.7
p0=0.3

# A small mesh: 3 x 8 cells, graded towards theta = 0 like the roll scene.
echo "running: gmsh -2 -format msh2 $geo"
"$gmsh" -2 -format msh2 -setnumber R1 $R1 -setnumber R0 $R0 \
  -setnumber Sector 90 -setnumber NR 3 -setnumber NTheta 8 \
  -setnumber GradeTheta 4 "$geo" -o quarter_roll.msh > gmsh.log 2>&1 ||
  { cat gmsh.log; fail "gmsh could not mesh $geo"; }
[ -s quarter_roll.msh ] || fail "gmsh wrote no mesh"
pass "gmsh meshed $geo"

cat > hydrostatic.prm <<PRM
subsection Geometry
  set Inner radius = $R1
  set Outer radius = $R0
  set Sector angle = 90
end
subsection Mesh
  set Source             = gmsh
  set Mesh file          = quarter_roll.msh
  set Global refinements = 1
end
subsection Boundary conditions
  set Inner arc (id 0)     = fixed
  set Outer arc (id 1)     = pressure
  set Symmetry edge (id 2) = symmetry
  set Far edge (id 3)      = symmetry
end
subsection Load
  set Pressure function = p0
  set p0                = $p0
end
PRM
quiet_output >> hydrostatic.prm

echo "running: rollnip hydrostatic.prm"
"$rollnip" hydrostatic.prm > rollnip.log 2>&1 ||
  { cat rollnip.log; fail "rollnip failed on the gmsh mesh"; }
head -n 1 rollnip.log
s=out/summary.txt
[ "$(summary_value $s status)" = converged ] || fail "status is not converged"
pass "status = converged"
cells="$(summary_value $s cells)"
[ "$cells" -eq 96 ] || fail "cells = $cells, expected 3 x 8 x 4 = 96"
pass "cells = 96 (3 x 8 gmsh quadrilaterals, refined once)"

check_abs_below "u_r_at_R0_0_mm" "$(summary_value $s u_r_at_R0_0_mm)" 1e-9
check_close "sigma_rr_min_MPa" "$(summary_value $s sigma_rr_min_MPa)" -$p0 1e-8
check_close "sigma_rr_max_MPa" "$(summary_value $s sigma_rr_max_MPa)" -$p0 1e-8
check_close "bond_sigma_rr_min_MPa" "$(summary_value $s bond_sigma_rr_min_MPa)" -$p0 1e-8
check_close "bond_sigma_rr_max_MPa" "$(summary_value $s bond_sigma_rr_max_MPa)" -$p0 1e-8
check_abs_below "sigma_rtheta_max_abs_MPa" \
  "$(summary_value $s sigma_rtheta_max_abs_MPa)" 1e-8
P_exact="$(awk -v p=$p0 -v r=$R0 'BEGIN { printf "%.10g", 2 * p * r }')"
check_rel_close "nip_load_P_N_per_mm (2 p0 R0)" \
  "$(summary_value $s nip_load_P_N_per_mm)" "$P_exact" 1e-8
