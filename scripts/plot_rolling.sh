#!/usr/bin/env bash
# Plots the rolling post-process of a nip sweep (doc/rolling.md): the
# dissipation density (mean over a turn) and the temperature over the
# cover's depth for every nip, and the rolling resistance and the
# temperatures against speed for every nip with a speed table.
#
# Usage: bash scripts/plot_rolling.sh DIR [PNG_PREFIX]
# (DIR: the Output/Directory of a run with Rolling/Enabled = true). Writes
# PNG_PREFIX_profile.png and PNG_PREFIX_speed.png (default prefix:
# DIR/rolling).
set -euo pipefail
me="plot_rolling.sh"
die() { echo "$me: $*" >&2; exit 1; }

[ "$#" -ge 1 ] || die "usage: bash scripts/plot_rolling.sh DIR [PNG_PREFIX]"
dir="${1%/}"
prefix="${2:-$dir/rolling}"
command -v gnuplot >/dev/null 2>&1 ||
  die "gnuplot not found; install the Debian package gnuplot-nox (bash scripts/setup.sh does)"
nips=()
if [ -f "$dir/rolling_profile.csv" ]; then
  nips+=(".")
else
  for d in "$dir"/nip-*/; do
    [ -f "$d/rolling_profile.csv" ] && nips+=("$(basename "$d")")
  done
fi
[ "${#nips[@]}" -gt 0 ] || die "no rolling_profile.csv in '$dir' or its nip-*/: was Rolling/Enabled = true?"

profile=""
speed=""
for n in "${nips[@]}"; do
  profile+="'$dir/$n/rolling_profile.csv' using 2:(\$4/1e6) with linespoints axes x1y1 title '$n: dissipation', "
  profile+="'$dir/$n/rolling_profile.csv' using 2:6 with lines dashtype 2 axes x1y2 title '$n: temperature', "
  if [ -f "$dir/$n/rolling_speeds.csv" ]; then
    speed+="'$dir/$n/rolling_speeds.csv' using 1:2 with linespoints axes x1y1 title '$n: F_r', "
    speed+="'$dir/$n/rolling_speeds.csv' using 1:7 with lines dashtype 2 axes x1y2 title '$n: T max', "
  fi
done

gnuplot <<GP
set datafile separator ','
set terminal pngcairo size 900,600
set key autotitle columnhead top right
set output '${prefix}_profile.png'
set xlabel 'depth below the surface [mm]'
set ylabel 'dissipation density, mean over a turn [MW/m^3]'
set y2label 'temperature [degC]'
set ytics nomirror
set y2tics
set grid
plot ${profile%, }
GP
echo "$me: wrote ${prefix}_profile.png"
if [ -n "$speed" ]; then
  unit="$(head -1 "$dir/${nips[0]}/rolling_speeds.csv" | cut -d, -f1 | sed 's/speed_//; s/_per_/\//')"
  gnuplot <<GP
set datafile separator ','
set terminal pngcairo size 900,600
set key top left
set output '${prefix}_speed.png'
set xlabel 'surface speed [$unit]'
set ylabel 'rolling resistance F_r [N/mm]'
set y2label 'largest cover temperature [degC]'
set ytics nomirror
set y2tics
set grid
plot ${speed%, }
GP
  echo "$me: wrote ${prefix}_speed.png"
fi
