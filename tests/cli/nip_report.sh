#!/usr/bin/env bash
# The nip report of parameters/engineering_nip.prm (a 250 mm roll, 13.5 mm
# cover of 60 Shore A, a 300 mm mating roll, 20, 40 and 60 kN/m, 600 m/min;
# level 2, 7154 DoFs, a few seconds):
#  - the converted inputs and the modulus estimate are echoed;
#  - nip_report.csv has a header with units and one row per nip, the loads
#    in kN/m as given (to the control tolerance, 1e-6);
#  - its 2b is twice the half-chord of nip_characteristic.csv (1e-9) and the
#    deformed y of the contact-edge node in the nip's outer_surface.csv
#    (1e-8); the mean pressure is P / 2b and the dwell time 2b / v (1e-9);
#  - the headline numbers are pinned: 2b, u0, peak pressure and dwell at
#    each load and E = 3.6051 MPa from Gent's relation, to a relative 1e-4
#    (the control and conformity tolerances are 1e-6; 1e-4 leaves room
#    for the direct solver's rounding on another machine);
#  - the estimated errors are in the report (2b's twice b's in
#    nip_characteristic.csv), positive, below 1 %, and on the screen as
#    value +- error;
#  - plot_results.sh draws nip_report.png (width and peak pressure against
#    the line load).
#
# Usage: bash nip_report.sh ROLLNIP PRM PLOT_SCRIPT
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 3 ] || fail "usage: nip_report.sh ROLLNIP PRM PLOT_SCRIPT"
rollnip="$1"
prm="$2"
plot="$3"
require_executable rollnip "$rollnip"
start_test nip_report

rc=0
"$rollnip" "$prm" > stdout.txt 2> stderr.txt || rc=$?
[ "$rc" -eq 0 ] || { cat stderr.txt; fail "exit code $rc"; }
pass "engineering_nip.prm runs, exit code 0"
grep -q "^Material: 60 Shore A, Gent (1958): E = 3.605.* MPa (an estimate from hardness)" stdout.txt ||
  fail "the modulus estimate is not echoed"
grep -q "^Geometry: roll diameter 250 mm, cover thickness 13.5 mm: R0 = 125 mm, R1 = 111.5 mm" stdout.txt ||
  fail "the geometry is not echoed"
grep -q "^Nip report (E = 3.605 MPa, an estimate from hardness" stdout.txt ||
  fail "no nip report on the screen"
pass "inputs, modulus estimate and nip report echoed on the screen"

dir=output/engineering_nip
report="$dir/nip_report.csv"
[ -f "$report" ] || fail "no $report"
header="nip,line_load_kN_per_m,line_load_N_per_mm,nip_width_2b_mm,indentation_u0_mm,peak_pressure_MPa,mean_pressure_MPa,surface_speed_m_per_min,dwell_time_ms,youngs_modulus_E_MPa,E_estimated_from_hardness,line_load_err_N_per_mm,nip_width_2b_err_mm,indentation_u0_err_mm,peak_pressure_err_MPa,mean_pressure_err_MPa,nip_width_2b_hertz_mm,peak_pressure_hertz_MPa,nip_width_2b_thin_layer_mm,peak_pressure_thin_layer_MPa,youngs_modulus_E_band_low_MPa,youngs_modulus_E_band_high_MPa,nip_width_2b_at_E_band_low_mm,nip_width_2b_at_E_band_high_mm"
[ "$(head -n 1 "$report")" = "$header" ] || fail "unexpected header: $(head -n 1 "$report")"
[ "$(($(wc -l < "$report") - 1))" -eq 3 ] || fail "expected 3 rows"
pass "header with units, 3 rows"

# cell ROW COLUMN_NAME FILE: a value of a CSV table (ROW counts from 1).
cell() {
  awk -F, -v r="$1" -v name="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) c = i }
    NR == r + 1 { print $c }' "$3"
}

expected_2b=(27.71325281 35.21952509 40.29746698)
expected_u0=(1.257634687 1.831875007 2.267502433)
expected_peak=(0.9737827911 1.577801076 2.106156332)
for n in 1 2 3; do
  load="$(cell $n line_load_kN_per_m "$report")"
  width="$(cell $n nip_width_2b_mm "$report")"
  P="$(cell $n line_load_N_per_mm "$report")"
  check_rel_close "nip $n load [kN/m]" "$load" "$((20 * n))" 1e-6
  b="$(cell $n half_chord_mm "$dir/nip_characteristic.csv")"
  check_rel_close "nip $n 2b against 2 half_chord_mm" "$width" "$(awk -v b="$b" 'BEGIN { printf "%.12g", 2 * b }')" 1e-9
  theta0="$(cell $n theta0_deg "$dir/nip_characteristic.csv")"
  edge_y="$(awk -F, -v t="$theta0" 'NR > 1 { d = $1 - t; if (d < 0) d = -d
              if (best == "" || d < best) { best = d; y = $5 } } END { printf "%.12g", y }' \
              "$dir/nip-0$n/outer_surface.csv")"
  check_rel_close "nip $n 2b against 2 y of the edge node in outer_surface.csv" "$width" "$(awk -v y="$edge_y" 'BEGIN { printf "%.12g", 2 * y }')" 1e-8
  check_rel_close "nip $n mean pressure = P / 2b" "$(cell $n mean_pressure_MPa "$report")" "$(awk -v p="$P" -v w="$width" 'BEGIN { printf "%.12g", p / w }')" 1e-9
  check_rel_close "nip $n dwell = 2b / (600 m/min) [ms]" "$(cell $n dwell_time_ms "$report")" "$(awk -v w="$width" 'BEGIN { printf "%.12g", w / 10 }')" 1e-9
  check_rel_close "nip $n 2b [mm]" "$width" "${expected_2b[n - 1]}" 1e-4
  check_rel_close "nip $n u0 [mm]" "$(cell $n indentation_u0_mm "$report")" "${expected_u0[n - 1]}" 1e-4
  check_rel_close "nip $n peak pressure [MPa]" "$(cell $n peak_pressure_MPa "$report")" "${expected_peak[n - 1]}" 1e-4
done
# The estimated errors (Accuracy/Error estimate, on by default): the
# report's are those of nip_characteristic.csv (2b: twice b's), each
# positive and below 1 % of its number on this mesh, and the screen shows
# every number with its +- error.
for n in 1 2 3; do
  width="$(cell $n nip_width_2b_mm "$report")"
  width_err="$(cell $n nip_width_2b_err_mm "$report")"
  b_err="$(cell $n half_chord_err_mm "$dir/nip_characteristic.csv")"
  check_rel_close "nip $n 2b error = 2 x b error" "$width_err" "$(awk -v e="$b_err" 'BEGIN { printf "%.12g", 2 * e }')" 1e-9
  for pair in "nip_width_2b_mm nip_width_2b_err_mm" "indentation_u0_mm indentation_u0_err_mm" \
              "peak_pressure_MPa peak_pressure_err_MPa" "mean_pressure_MPa mean_pressure_err_MPa"; do
    set -- $pair
    awk -v v="$(cell $n "$1" "$report")" -v e="$(cell $n "$2" "$report")" \
      'BEGIN { exit !(e > 0 && e < 0.01 * v) }' ||
      fail "nip $n: $2 = $(cell $n "$2" "$report") is not in (0, 1 % of $1)"
  done
done
pass "estimated errors of 2b, u0, peak and mean pressure: positive, below 1 %, 2b's twice b's"
[ "$(grep -A 4 '^Nip report' stdout.txt | grep -c ' +- ')" -eq 3 ] ||
  fail "the nip report on the screen does not show the numbers with +- errors"
pass "the screen report shows each number +- its error"

check_rel_close "E [MPa]" "$(cell 1 youngs_modulus_E_MPa "$report")" 3.605072697 1e-8
[ "$(cell 1 E_estimated_from_hardness "$report")" = yes ] || fail "E not flagged as an estimate"
pass "E flagged as estimated from hardness"
[ "$(summary_value "$dir/nip-01/summary.txt" modulus_source)" = "estimate from hardness 60 Shore A, Gent (1958)" ] ||
  fail "summary.txt does not name the modulus source"
pass "summary.txt: modulus_source = estimate from hardness 60 Shore A, Gent (1958)"

bash "$plot" "$dir" > plot.txt 2>&1 || { cat plot.txt; fail "plot_results.sh failed"; }
[ -s "$dir/plots/nip_report.png" ] || fail "no plots/nip_report.png"
pass "plot_results.sh draws plots/nip_report.png"
