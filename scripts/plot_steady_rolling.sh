#!/usr/bin/env bash
# Plots the full steady rolling of a run with Rolling/Full steady rolling =
# true (doc/rolling.md, section 7): the rolling resistance against V tau / b
# (both ways: moment of the contact forces and dissipation over speed,
# beside the first-order route), the contact pressure against the angle
# at every speed (the inlet at theta < 0), the cover's temperatures against
# V tau / b (full and first-order heat source) and the temperature over
# the cover's thickness at every speed.
#
# Usage: bash scripts/plot_steady_rolling.sh DIR [PNG_PREFIX]
# (DIR holds rolling_full.csv, rolling_full_pressure.csv and
# rolling_full_profile.csv). Writes PNG_PREFIX_resistance.png,
# PNG_PREFIX_pressure.png, PNG_PREFIX_temperature.png and
# PNG_PREFIX_profile.png (default prefix: DIR/rolling_full).
set -euo pipefail
me="plot_steady_rolling.sh"
die() { echo "$me: $*" >&2; exit 1; }

[ "$#" -ge 1 ] || die "usage: bash scripts/plot_steady_rolling.sh DIR [PNG_PREFIX]"
dir="${1%/}"
prefix="${2:-$dir/rolling_full}"
command -v gnuplot >/dev/null 2>&1 ||
  die "gnuplot not found; install the Debian package gnuplot-nox (bash scripts/setup.sh does)"
[ -f "$dir/rolling_full.csv" ] ||
  die "no rolling_full.csv in '$dir': was Rolling/Full steady rolling = true?"
[ -f "$dir/rolling_full_pressure.csv" ] || die "no rolling_full_pressure.csv in '$dir'"
[ -f "$dir/rolling_full_profile.csv" ] || die "no rolling_full_profile.csv in '$dir'"

# One gnuplot curve per speed of the pressure table.
speeds="$(awk -F, 'NR > 1 { print $1 }' "$dir/rolling_full_pressure.csv" | uniq)"
pressure=""
for v in $speeds; do
  pressure+="'< awk -F, \"NR > 1 && \\\$1 == $v\" $dir/rolling_full_pressure.csv' using 2:3 with linespoints pointsize 0.4 title '$v m/min', "
done
# One curve per speed of the temperature over the thickness.
profile=""
for v in $(awk -F, 'NR > 1 { print $1 }' "$dir/rolling_full_profile.csv" | uniq); do
  profile+="'< awk -F, \"NR > 1 && \\\$1 == $v\" $dir/rolling_full_profile.csv' using 3:6 with linespoints pointsize 0.4 title '$v m/min', "
done

gnuplot <<GNUPLOT
set datafile separator ','
set terminal pngcairo size 900,600
set output '${prefix}_resistance.png'
set logscale x
set xlabel 'V tau / b'
set ylabel 'rolling resistance F_r [N/mm]'
set key top left
set grid
set yrange [0:*]
plot '$dir/rolling_full.csv' using 3:6 with linespoints title 'full: dissipation / V', \
     '$dir/rolling_full.csv' using 3:5 with points pointtype 6 title 'full: moment of the contact forces / R0', \
     '$dir/rolling_full.csv' using 3:(\$3 <= 0.5 ? \$7 : 1/0) with lines dashtype 2 title 'first order (to V tau / b = 0.5)'
set output '${prefix}_pressure.png'
unset logscale x
set xlabel 'theta [deg] (material enters at theta < 0)'
set ylabel 'contact pressure [MPa]'
set key top right
plot ${pressure%, }
set output '${prefix}_temperature.png'
set logscale x
set xlabel 'V tau / b'
set ylabel 'cover temperature [degC]'
set key top left
set yrange [*:*]
plot '$dir/rolling_full.csv' using 3:21 with linespoints title 'full: largest', \
     '$dir/rolling_full.csv' using 3:19 with linespoints title 'full: bond', \
     '$dir/rolling_full.csv' using 3:20 with linespoints title 'full: surface', \
     '$dir/rolling_full.csv' using 3:(\$3 <= 0.5 ? \$24 : 1/0) with lines dashtype 2 title 'first order: largest (to V tau / b = 0.5)'
set output '${prefix}_profile.png'
unset logscale x
set xlabel 'depth below the surface [mm]'
set ylabel 'temperature, full steady rolling [degC]'
set key outside right
plot ${profile%, }
GNUPLOT
echo "$me: wrote ${prefix}_resistance.png, ${prefix}_pressure.png, ${prefix}_temperature.png and ${prefix}_profile.png"
