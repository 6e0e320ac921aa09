#!/usr/bin/env bash
# The engineer's nip report in both unit systems (doc/engineering_inputs.md,
# sections 3, 5 and 6), on the nip of parameters/engineering_nip.prm at
# 40 kN/m on mesh level 1 (a 250 mm roll, 13.5 mm cover of 60 Shore A,
# 300 mm mating roll):
#  - US: the same nip given as 228.4059 PLI at 1969 fpm with Output/Units
#    = US and Verbosity = quiet prints only the report (no iteration log,
#    nothing on standard error) and gives the SI run's numbers converted
#    (in = 25.4 mm, psi = 6894.757 Pa; relative 1e-5, ten times the
#    control tolerance), its columns named in_, psi, pli, fpm;
#  - the comparisons at the same load: Hertz's 2b = 2 sqrt(4 P R / (pi E*))
#    and peak 2 P / (pi b) with E* = 4 G and 1/R = 1/125 + 1/150 (1e-9);
#    the thin layer nan (its b/h is 2.5, below 4); P_linear nan (off);
#  - the modulus band of 60 Shore A: 3.4779 (ISO 48 IRHD) to 5.8844 MPa
#    (log-linear), and the width at its upper end equals an independent
#    run with C1 = 5.8844/6 MPa at 40 kN/m (relative 2e-5): the scaling
#    the report uses is exact;
#  - two covered rolls (a 400 mm roll, 15 mm of 90 Shore A, as the mate):
#    the report gives each roll's indentation, on the screen and as
#    roll_indentation_mm and mating_roll_indentation_mm, equal to
#    contact.txt's (1e-7, its 8 digits); the band is nan (not a one-material scene);
#  - a guard rail: at 120 kN/m u0/h passes 0.23 and a one-line warning
#    names the limit and its source; the run still succeeds.
#
# Usage: bash engineer_units.sh ROLLNIP
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 1 ] || fail "usage: engineer_units.sh ROLLNIP"
rollnip="$(realpath "$1")"
require_executable rollnip "$rollnip"
start_test engineer_units

# scene DIR MATERIAL_LINES CONTACT_LINES OUTPUT_LINES: a .prm on stdout.
scene()
{
  engineer_roll_scene
  cat <<PRM
subsection Material
$2
end
subsection Contact
  set Mode              = load
  set Indenter diameter = 300
$3
end
subsection Accuracy
  set Error estimate = false
end
subsection Output
  set Directory = $1
  set Write VTU = false
$4
end
PRM
}

scene si "  set Hardness = 60" "  set Load unit = kN/m
  set Values = 40
  set Surface speed = 600
  set Compare with linear theory = false" "" > si.prm
scene us "  set Hardness = 60
  set Hardness scale = shore a" "  set Load unit = PLI
  set Values = 228.40588618930587
  set Surface speed = 1969 fpm" "  set Units = us
  set Verbosity = QUIET" > us.prm
scene stiff "  set C1 = 0.98072839504
  set C2 = 0" "  set Load unit = kN/m
  set Values = 40" "" > stiff.prm
scene guard "  set Hardness = 60" "  set Load unit = kN/m
  set Values = 120" "  set Verbosity = quiet" > guard.prm

cat > two.prm <<PRM
subsection Geometry
  set Roll diameter   = 250
  set Cover thickness = 13.5
end
subsection Mesh
  set Radial cells          = 8
  set Circumferential cells = 18
  set Global refinements    = 1
end
subsection Material
  set Hardness = 60
end
subsection Contact
  set Mode      = load
  set Load unit = kN/m
  set Values    = 40
end
subsection Mating roll
  set Type = covered roll
  subsection Geometry
    set Roll diameter   = 400
    set Cover thickness = 15
  end
  subsection Material
    set Hardness = 90
  end
  subsection Mesh
    set Radial cells          = 8
    set Circumferential cells = 18
    set Global refinements    = 1
  end
end
subsection Accuracy
  set Error estimate = false
end
subsection Output
  set Directory = two
  set Write VTU = false
  set Verbosity = quiet
end
PRM

for run in si us stiff guard two; do
  rc=0
  "$rollnip" $run.prm > $run.out 2> $run.err || rc=$?
  [ "$rc" -eq 0 ] || { cat $run.err; fail "$run.prm: exit code $rc"; }
done
pass "the SI, US, stiff, guard-rail and two-roll runs succeed"

# Quiet: the report only.
grep -q "^Nip report" us.out || fail "quiet: no nip report on the screen"
! grep -q "Contact iteration\|Nip characteristic\|Newton" us.out ||
  fail "quiet: the iteration log is on the screen"
[ ! -s us.err ] || { cat us.err; fail "quiet: standard error is not empty"; }
[ "$(wc -l < us.out)" -le 12 ] || fail "quiet: $(wc -l < us.out) lines on the screen"
pass "Verbosity = QUIET: $(wc -l < us.out) lines, the report only"
grep -q "width 2b \[in\]" us.out && grep -q "surface speed 1969 fpm" us.out ||
  fail "the US report is not in inches and fpm"
pass "the US report on the screen is in in, psi and fpm"

si=si/nip_report.csv
us=us/nip_report.csv
for column in line_load_pli nip_width_2b_in indentation_u0_in peak_pressure_psi \
              mean_pressure_psi surface_speed_fpm youngs_modulus_E_psi; do
  head -n 1 "$us" | tr , '\n' | grep -qx "$column" || fail "$us: no column $column"
done
pass "US columns: line_load_pli, nip_width_2b_in, peak_pressure_psi, surface_speed_fpm, ..."

mm=25.4
psi=0.006894757293168361
v() { csv_value "$1" "$2" 1; }
check_rel_close "US load [pli] in N/mm" "$(awk -v p="$(v $us line_load_pli)" 'BEGIN { printf "%.12g", p * 0.17512683524647636 }')" 40 1e-6
for pair in "nip_width_2b_in nip_width_2b_mm $mm" "indentation_u0_in indentation_u0_mm $mm" \
            "peak_pressure_psi peak_pressure_MPa $psi" "mean_pressure_psi mean_pressure_MPa $psi" \
            "youngs_modulus_E_psi youngs_modulus_E_MPa $psi" \
            "nip_width_2b_hertz_in nip_width_2b_hertz_mm $mm" \
            "nip_width_2b_at_E_band_high_in nip_width_2b_at_E_band_high_mm $mm"; do
  set -- $pair
  check_rel_close "US $1 x $3 against SI $2" \
    "$(awk -v a="$(v $us "$1")" -v f="$3" 'BEGIN { printf "%.12g", a * f }')" "$(v $si "$2")" 1e-5
done
check_rel_close "surface speed [fpm]" "$(v $us surface_speed_fpm)" 1969 1e-12
check_rel_close "dwell = 2b / (1969 fpm) [ms]" "$(v $us dwell_time_ms)" \
  "$(awk -v w="$(v $si nip_width_2b_mm)" 'BEGIN { printf "%.12g", w / (1969 * 0.3048 / 60) }')" 1e-5

# The comparisons at the user's load.
G="$(awk -v e="$(v $si youngs_modulus_E_MPa)" 'BEGIN { printf "%.15g", e / 3 }')"
# P as solved (40 kN/m to the control tolerance).
P="$(v $si line_load_N_per_mm)"
b="$(awk -v g="$G" -v P="$P" 'BEGIN { R = 1 / (1 / 125 + 1 / 150); printf "%.15g", sqrt(4 * P * R / (3.141592653589793 * 4 * g)) }')"
check_rel_close "Hertz 2b at 40 kN/m [mm]" "$(v $si nip_width_2b_hertz_mm)" "$(awk -v b="$b" 'BEGIN { printf "%.15g", 2 * b }')" 1e-9
check_rel_close "Hertz peak at 40 kN/m [MPa]" "$(v $si peak_pressure_hertz_MPa)" "$(awk -v b="$b" -v P="$P" 'BEGIN { printf "%.15g", 2 * P / (3.141592653589793 * b) }')" 1e-9
[ "$(v $si nip_width_2b_thin_layer_mm)" = nan ] && [ "$(v $si peak_pressure_thin_layer_MPa)" = nan ] ||
  fail "the thin-layer comparison is not nan at b/h = 2.5"
[ "$(csv_value si/nip_characteristic.csv P_linear_N_per_mm 1)" = nan ] ||
  fail "P_linear is not nan with linear theory off"
pass "thin layer nan (b/h below 4), P_linear nan (linear theory off)"

# The modulus band and the width at its ends.
check_rel_close "E band low [MPa]" "$(v $si youngs_modulus_E_band_low_MPa)" 3.477901818 1e-8
check_rel_close "E band high [MPa]" "$(v $si youngs_modulus_E_band_high_MPa)" 5.884370370 1e-8
check_rel_close "2b at E_high against a run with C1 = E_high / 6" \
  "$(v $si nip_width_2b_at_E_band_high_mm)" "$(v stiff/nip_report.csv nip_width_2b_mm)" 2e-5
awk -v lo="$(v $si nip_width_2b_at_E_band_high_mm)" -v w="$(v $si nip_width_2b_mm)" \
    -v hi="$(v $si nip_width_2b_at_E_band_low_mm)" 'BEGIN { exit !(lo < w && w < hi) }' ||
  fail "the band's widths do not bracket the nip width"
pass "the band's widths bracket 2b"

# The guard rail.
grep -q "^rollnip: warning: nip 1: indentation/thickness u0/h = .* exceeds 0.23, beyond the nips whose accuracy was measured (u0/h up to 0.224, doc/accuracy.md)" guard.err ||
  { cat guard.err; fail "no u0/h warning at 120 kN/m"; }
[ "$(grep -vc '^rollnip: warning: ' guard.err)" -eq 0 ] || fail "standard error holds more than warning lines"
pass "120 kN/m: the u0/h warning ($(grep -c . guard.err) warning line(s)), exit code 0"

# Two covered rolls: each roll's indentation.
grep -q "roll u0 \[mm\] *mate u0 \[mm\]" two.out || { cat two.out; fail "the two-roll report has no roll and mate u0"; }
for pair in "roll_indentation_mm roll_indentation_mm" "mating_roll_indentation_mm mating_roll_indentation_mm"; do
  set -- $pair
  check_rel_close "two rolls: $1 against contact.txt" "$(v two/nip_report.csv "$1")" "$(summary_value two/contact.txt "$2")" 1e-7
done
[ "$(v two/nip_report.csv nip_width_2b_at_E_band_low_mm)" = nan ] || fail "two rolls: a band width that the scaling does not give"
pass "two rolls: each roll's indentation on the screen and in the report; no band widths"
