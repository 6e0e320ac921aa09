#!/usr/bin/env bash
# The load on the screen is the one the discretisation applies: for the
# parabolic pressure of parameters/parabolic_pressure.prm (p0 = 0.5 MPa on
# theta0 = 10 deg of R0 = 60.7 mm) the resultant --validate prints agrees
# with the exact integral -R0 int_0^theta0 f(theta) (cos, sin) dtheta to
# 0.5 % (Gauss points on the mesh; the zone's edge is a node here), and the
# same pressure on 0.1745 deg (theta0 typed in radians) over 0.5 deg cells
# is refused (tests/cli/bad_input/pressure_zone_in_radians.prm checks the
# line).
#
# Usage: bash applied_load.sh ROLLNIP PRESSURE_PRM
#   PRESSURE_PRM  parameters/parabolic_pressure.prm
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

scene_test_args applied_load PRESSURE_PRM "$@"

cp "$scene" run.prm
"$rollnip" --validate run.prm > stdout.txt 2> stderr.txt || {
  cat stdout.txt stderr.txt
  fail "--validate failed"
}
line="$(grep '^Load: ' stdout.txt)" || fail "no 'Load:' line"
echo "$line"
[[ "$line" =~ resultant\ of\ the\ discrete\ load\ on\ the\ undeformed\ arc\ \(([-0-9.e+]+),\ ([-0-9.e+]+)\)\ N/mm ]] ||
  fail "the line does not give the discrete resultant"
fx="${BASH_REMATCH[1]}"
fy="${BASH_REMATCH[2]}"
# The exact resultant by Simpson's rule (2000 intervals).
read -r ex ey < <(awk 'BEGIN {
  pi = atan2(0, -1); R0 = 60.7; p0 = 0.5; t0 = 10 * pi / 180; n = 2000
  for (i = 0; i <= n; ++i) {
    t = t0 * i / n; w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2)
    f = p0 * (1 - (t / t0) ^ 2)
    sx += w * f * cos(t); sy += w * f * sin(t)
  }
  h = t0 / n / 3
  printf "%.8g %.8g\n", -R0 * h * sx, -R0 * h * sy }')
for c in "x $fx $ex" "y $fy $ey"; do
  read -r name got exact <<< "$c"
  awk -v g="$got" -v e="$exact" 'BEGIN { d = g / e - 1; exit !((d < 0 ? -d : d) < 5e-3) }' ||
    fail "resultant $name: printed $got N/mm, exact $exact N/mm"
  pass "resultant $name: printed $got N/mm, exact $exact N/mm (within 0.5 %)"
done
