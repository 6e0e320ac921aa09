#!/usr/bin/env bash
# scripts/plot_results.sh speaks the user's units and not the solver's.
#
# Usage: bash plot_units.sh ROLLNIP PLOT_RESULTS_SH
#
# Two quick-form nips (parameters/engineering_nip.prm's roll): 228.4 and
# 342.6 pli, and 40 kN/m. Checks:
#   - every nip is labelled by its load as nip_report.csv gives it
#     ("P = 228.4 pli", "P = 40 kN/m"), read back from the SVG text;
#   - the pli run's figures are in inches and psi: no axis or title says mm
#     or MPa, and the pressure, nip width and indentation axes say (psi) and
#     (in); the kN/m run's say (mm) and (MPa);
#   - no legend or title uses the solver's words (theta_0 labels, "imposed
#     f", "knots", "reference nip angle");
#   - the indentation-against-load figure is drawn;
#   - ROLLNIP_UNITS=US draws the kN/m run in inches too.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 2 ] || fail "usage: plot_units.sh ROLLNIP PLOT_RESULTS_SH"
rollnip="$1"
plot="$2"
require_executable rollnip "$rollnip"
start_test plot_units

roll=(--diameter 250 --cover 13.5 --hardness 60A --mate 300 --speed 600m/min)
"$rollnip" nip "${roll[@]}" --load 228.4,342.6pli --output us >us.log 2>&1 || { tail us.log; fail "pli run failed"; }
"$rollnip" nip "${roll[@]}" --load 40kN/m --output si >si.log 2>&1 || { tail si.log; fail "kN/m run failed"; }
bash "$plot" us >plot_us.log 2>&1 || { cat plot_us.log; fail "plot_results.sh failed on the pli run"; }
bash "$plot" si >plot_si.log 2>&1 || { cat plot_si.log; fail "plot_results.sh failed on the kN/m run"; }

# The visible text of an SVG (axis labels, titles, legends), one per line.
svg_text() { grep -o '<tspan[^>]*>[^<]*</tspan>' "$1" | sed 's/<[^>]*>//g'; }

for run in us si; do
  for figure in indentation nip_report nip_pressure contact_pressure nip_characteristic bond_stresses; do
    [ -s "$run/plots/$figure.png" ] && [ -s "$run/plots/$figure.svg" ] || fail "$run: $figure.png/.svg missing"
  done
  for f in "$run"/plots/*.svg; do
    bad="$(svg_text "$f" | grep -E 'θ_0|θ0|imposed|knot|reference nip angle' || true)"
    [ -z "$bad" ] || fail "$f uses the solver's words: $bad"
  done
done
pass "all figures drawn, indentation included; no solver words in titles or legends"

python3 - <<'PY' || fail "load labels"
import csv, re, subprocess, sys
def text(path):
    return re.sub(r"<[^>]*>", "", "\n".join(re.findall(r"<tspan[^>]*>[^<]*</tspan>", open(path).read())))
def check(ok, message):
    print(("ok:   " if ok else "FAIL: ") + message)
    if not ok:
        sys.exit(1)
for run, column, unit in (("us", "line_load_pli", "pli"), ("si", "line_load_kN_per_m", "kN/m")):
    rows = list(csv.DictReader(open(f"{run}/nip_report.csv")))
    t = text(f"{run}/plots/nip_pressure.svg")
    labels = [float(x) for x in re.findall(r"P = ([0-9.]+) " + re.escape(unit), t)]
    loads = [float(r[column]) for r in rows]
    check(len(set(labels)) == len(loads) and
          all(any(abs(l / x - 1) < 1e-3 for l in labels) for x in loads),
          f"{run}: nips labelled {sorted(set(labels))} {unit}, nip_report.csv has {loads}")
PY

us_text="$(for f in us/plots/*.svg; do svg_text "$f"; done)"
if grep -E '\((mm|MPa)\)|\[(mm|MPa)\]' <<<"$us_text"; then fail "the pli run's figures mention mm or MPa"; fi
for label in 'pressure (psi)' 'nip width 2b, deformed (in)' 'approach of the roll axes (in)' 'line load (pli)'; do
  grep -qF "$label" <<<"$us_text" || fail "the pli run's figures have no '$label'"
done
pass "pli run: inches and psi only"
si_text="$(for f in si/plots/*.svg; do svg_text "$f"; done)"
for label in 'pressure (MPa)' 'nip width 2b, deformed (mm)' 'line load (kN/m)'; do
  grep -qF "$label" <<<"$si_text" || fail "the kN/m run's figures have no '$label'"
done
pass "kN/m run: mm and MPa"
ROLLNIP_UNITS=US bash "$plot" si >/dev/null 2>&1 || fail "ROLLNIP_UNITS=US failed"
svg_text si/plots/indentation.svg | grep -qF 'approach of the roll axes (in)' ||
  fail "ROLLNIP_UNITS=US did not draw the kN/m run in inches"
pass "ROLLNIP_UNITS=US: the kN/m run in inches"
