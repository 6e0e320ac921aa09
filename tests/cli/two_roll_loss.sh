#!/usr/bin/env bash
# The covered mating roll's own loss (Rolling with Mating roll/Type =
# covered roll, doc/rolling.md). Two identical rolls pressed together
# press each other as a roll presses a rigid plane (symmetry about the
# common tangent, the same surface speed): each roll's first-order F_r,
# heat and temperatures equal the single roll's against a flat rigid
# plane (Indenter radius = inf) at the same load, to the two-roll
# iteration's tolerance (same mesh on both: not a discretisation error;
# measured 3e-7, required 1e-3), and the two rolls' equal each other. A
# rigid mate has no loss of its own.
#
# Usage: bash two_roll_loss.sh ROLLNIP
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 1 ] || fail "usage: two_roll_loss.sh ROLLNIP"
rollnip="$1"
require_executable rollnip "$rollnip"
start_test two_roll_loss

cover="$(engineer_roll_scene)
subsection Material
  set C1 = 0.6
  set C2 = 0
end"

# run NAME EXTRA: a 250 mm roll at 20 N/mm, 600 m/min, output in NAME/.
run()
{
  cat > "$1.prm" <<PRM
$cover
subsection Contact
  set Mode                       = load
  set Values                     = 20
  set Compare with linear theory = false
$2
end
subsection Rolling
  set Enabled                   = true
  set Surface speed             = 600
  set Loss tangent              = 0.1
  set Loss tangent frequency    = 500
  set Heat transfer coefficient = 30
  set Ambient temperature       = 25
  set Core temperature          = 35
end
PRM
  run_quiet_scene "$1"
}

run flat "  set Indenter radius = inf"
run pair "end
subsection Mating roll
  set Type = covered roll
${cover//subsection /  subsection }"

check_rel_close "pair: P" "$(contact_value pair nip_load_P_N_per_mm)" \
  "$(contact_value flat nip_load_P_N_per_mm)" 1e-5
for q in rolling_resistance:mate_rolling_resistance \
  cover_max_temperature:mate_cover_max_temperature \
  cover_surface_temperature:mate_cover_surface_temperature; do
  roll="${q%%:*}"
  mate="${q##*:}"
  unit=_N_per_mm
  [[ "$roll" == *temperature ]] && unit=_degC
  f="$(contact_value flat "$roll$unit")"
  check_rel_close "pair: roll's $roll against the flat plane's" \
    "$(contact_value pair "$roll$unit")" "$f" 1e-3
  check_rel_close "pair: mating roll's $mate against the flat plane's" \
    "$(contact_value pair "$mate$unit")" "$f" 1e-3
  check_rel_close "pair: mating roll's $mate against the roll's" \
    "$(contact_value pair "$mate$unit")" "$(contact_value pair "$roll$unit")" 1e-3
done
check_rel_close "pair: drive power of both" \
  "$(contact_value pair pair_drive_power_W_per_m)" \
  "$(awk -v p="$(contact_value flat rolling_drive_power_W_per_m)" \
    'BEGIN { printf "%.12g", 2 * p }')" 1e-3

# The mate's own cover: a mate 1000 times stiffer, of the same size, is
# loaded by the same pressure as the roll, mirrored; it strains 1000 times
# less and loses 1000 times less (D ~ G eps'^2) than the roll would in
# linear theory, so its F_r over the roll's is 1/1000 times the roll's
# linear over finite-strain loss (0.93 for the example, doc/rolling.md
# section 5): between 0.85e-3 and 1e-3. A mate without hysteresis
# (Hysteresis = own, tau = 0) loses nothing while the roll's loss stays
# the pair's.
run stiff "end
subsection Mating roll
  set Type = covered roll
${cover//subsection /  subsection }
end
subsection Mating roll
  subsection Material
    set C1 = 600
  end"
ratio="$(awk -v m="$(contact_value stiff mate_rolling_resistance_N_per_mm)" \
  -v r="$(contact_value stiff rolling_resistance_N_per_mm)" \
  'BEGIN { printf "%.6g", m / r }')"
check_less "mate 1000 times stiffer: its F_r over the roll's" "$ratio" 1e-3
check_less "mate 1000 times stiffer: 0.85e-3 against its F_r over the roll's" \
  0.85e-3 "$ratio"
run lossless "end
subsection Mating roll
  set Type = covered roll
${cover//subsection /  subsection }
end
subsection Rolling
  subsection Mating roll
    set Hysteresis         = own
    set Viscoelastic model = kelvin-voigt
    set Retardation time   = 0
  end"
check_abs_below "mate without hysteresis: its F_r" \
  "$(contact_value lossless mate_rolling_resistance_N_per_mm)" 1e-300
check_rel_close "mate without hysteresis: the roll's F_r against the pair's" \
  "$(contact_value lossless rolling_resistance_N_per_mm)" \
  "$(contact_value pair rolling_resistance_N_per_mm)" 1e-6
[ "$(contact_value flat mate_rolling_resistance_N_per_mm)" = 0 ] ||
  fail "a rigid plane has a loss of its own"
pass "a rigid mate: no loss of its own"
