#!/usr/bin/env bash
# A cover that softens as it heats (Rolling/Temperature dependence,
# doc/rolling.md): the fixed point of nip, loss, temperature and modulus,
# on parameters/rolling_heat.prm at 20 kN/m (Global refinements 1).
# - A zero coefficient (and no WLF shift) is today's run: every number of
#   contact.txt the same to the last digit written.
# - A uniform temperature (no loss, air and core at 60 degC) with
#   c = 0.01/K about 20 degC gives the nip of a cover whose C1 is
#   exp(-0.4) times as large, solved directly: theta0, u0, P, the peak
#   pressure and 2b agree to the contact iteration's tolerance (1e-5).
# - A coefficient of 1e-9/K runs the whole iteration (nip solved again)
#   and changes the nip by less than the tolerance.
# - c = 0.01/K with the example's loss: the fixed point converges, its
#   contraction (the ratio of successive temperature changes) is below
#   0.5, the heat made leaves through the air and the core to 1e-6, and
#   the softened nip is wider than the constant-modulus one.
# - A WLF shift alone (C1 = 8.86, C2 = 101.6 K about the core's 35 degC)
#   leaves the nip as it is and lowers the loss (a warmer cover relaxes
#   faster).
#
# Usage: bash thermal_softening.sh ROLLNIP ROLLING_HEAT_PRM
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

scene_test_args thermal_softening ROLLING_HEAT_PRM "$@"

# run NAME EXTRA: the example at 20 kN/m with EXTRA appended, output in
# NAME/.
run()
{
  sed -e 's/Global refinements *= *2/Global refinements = 1/' \
    -e 's/Hardness *= *60/C1 = 0.6/' \
    -e 's/C2\/C1 ratio *= *0/C2 = 0/' \
    -e '/Hardness scale/d' "$scene" > "$1.prm"
  cat >> "$1.prm" <<PRM
subsection Contact
  set Values = 20
end
$2
PRM
  run_quiet_scene "$1"
}

run plain ""
run zero "subsection Rolling
  subsection Temperature dependence
    set Modulus temperature coefficient = 0
    set WLF C1 = 0
  end
end"
if diff <(grep -v wall_time plain/contact.txt) \
  <(grep -v wall_time zero/contact.txt) > /dev/null; then
  pass "c = 0, C1 = 0: contact.txt as without Temperature dependence"
else
  fail "c = 0 changed contact.txt"
fi

uniform="subsection Rolling
  set Viscoelastic model  = kelvin-voigt
  set Retardation time    = 0
  set Ambient temperature = 60
  set Core temperature    = 60
PRM_MORE
end"
run uniform "${uniform/PRM_MORE/subsection Temperature dependence
    set Reference temperature           = 20
    set Modulus temperature coefficient = 0.01
  end}"
C1="$(awk 'BEGIN { printf "%.15g", 0.6 * exp(-0.4) }')"
run direct "${uniform/PRM_MORE/}
subsection Material
  set C1 = $C1
end"
check_rel_close "modulus factor at 60 degC" \
  "$(contact_value uniform thermal_modulus_factor_min)" \
  "$(awk 'BEGIN { printf "%.15g", exp(-0.4) }')" 1e-7
for key in half_nip_angle_theta0_deg indentation_u0_mm nip_load_P_N_per_mm \
  peak_pressure_MPa; do
  check_rel_close "uniform 60 degC, c = 0.01: $key against C1 = $C1" \
    "$(contact_value uniform "$key")" "$(contact_value direct "$key")" 1e-5
done
check_rel_close "uniform 60 degC: 2b against C1 = $C1" \
  "$(csv_value uniform/nip_report.csv nip_width_2b_mm 1)" \
  "$(csv_value direct/nip_report.csv nip_width_2b_mm 1)" 1e-5

run tiny "subsection Rolling
  subsection Temperature dependence
    set Modulus temperature coefficient = 1e-9
  end
end"
check_less "c = 1e-9: no pass against its passes" 0 "$(contact_value tiny thermal_passes)"
for key in half_nip_angle_theta0_deg rolling_resistance_N_per_mm \
  cover_max_temperature_degC; do
  check_rel_close "c = 1e-9: $key against c = 0" \
    "$(contact_value tiny "$key")" "$(contact_value plain "$key")" 1e-5
done

run soft "subsection Rolling
  subsection Temperature dependence
    set Reference temperature           = 35
    set Modulus temperature coefficient = 0.01
    set Temperature tolerance           = 1e-4
  end
end"
[ "$(contact_value soft thermal_converged)" = true ] ||
  fail "c = 0.01: the fixed point did not converge"
check_less "c = 0.01: contraction" "$(contact_value soft thermal_contraction)" 0.5
gen="$(contact_value soft heat_generated_W_per_m)"
out="$(awk -v a="$(contact_value soft heat_to_air_W_per_m)" \
  -v c="$(contact_value soft heat_to_core_W_per_m)" 'BEGIN { printf "%.12g", a + c }')"
check_rel_close "c = 0.01: heat to air + core against heat made" "$out" \
  "$gen" 1e-6
check_less "c = 0.01: constant-modulus 2b" \
  "$(contact_value soft constant_modulus_nip_width_2b_mm)" \
  "$(csv_value soft/nip_report.csv nip_width_2b_mm 1)"

run shift "subsection Rolling
  subsection Temperature dependence
    set Reference temperature = 35
    set WLF C1                = 8.86
    set WLF C2                = 101.6
  end
end"
check_rel_close "WLF alone: theta0 as at the constant modulus" \
  "$(contact_value shift half_nip_angle_theta0_deg)" \
  "$(contact_value plain half_nip_angle_theta0_deg)" 1e-12
check_less "WLF alone: F_r" "$(contact_value shift rolling_resistance_N_per_mm)" \
  "$(contact_value plain rolling_resistance_N_per_mm)"
