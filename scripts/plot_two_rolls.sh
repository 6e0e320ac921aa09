#!/usr/bin/env bash
# Plots a two-roll nip sweep (Mating roll/Type = covered roll): the contact
# pressure of both rolls over the deformed contact coordinate x2 (they must
# lie on each other: the same pressure at the same deformed point), and the
# deformed surfaces of both rolls near the last nip, the mating roll turned
# into the first roll's frame (x = D - x_mate, with D the distance of the
# centres: the sum of both surfaces' x on the line of centres).
#
# Usage: bash scripts/plot_two_rolls.sh RUN_DIR [PNG_PREFIX]
# (RUN_DIR: the Output/Directory of the run; doc/two_rolls.md gives the
# command). Writes PNG_PREFIX_pressure.png and PNG_PREFIX_profiles.png
# (default prefix: RUN_DIR/two_rolls).
set -euo pipefail
me="plot_two_rolls.sh"
die() { echo "$me: $*" >&2; exit 1; }

[ "$#" -ge 1 ] || die "usage: bash scripts/plot_two_rolls.sh RUN_DIR [PNG_PREFIX]"
run="${1%/}"
prefix="${2:-$run/two_rolls}"
command -v gnuplot >/dev/null 2>&1 ||
  die "gnuplot not found; install the Debian package gnuplot-nox (bash scripts/setup.sh does)"
nips=()
for d in "$run"/nip-*/ "$run"/; do
  [ -f "$d/mating_roll/outer_surface.csv" ] && nips+=("${d%/}")
done
[ "${#nips[@]}" -gt 0 ] ||
  die "no mating_roll/outer_surface.csv in '$run' or its nip-*/: is it a two-roll run (Mating roll/Type = covered roll) with Output/Write CSV = true?"
last="${nips[-1]}"

plots=""
colour=1
# Each nip's load in the run's unit: its row of nip_report.csv, whose second
# column names the unit (line_load_kN_per_m, line_load_pli, ...).
report="$run/nip_report.csv"
unit="N/mm"
if [ -f "$report" ]; then
  unit="$(head -n 1 "$report" | tr -d '\r' | cut -d, -f2 | sed 's/^line_load_//; s/^total_force_//; s/_per_/\//')"
fi
for nip in "${nips[@]}"; do
  row=$((colour + 1))
  if [ -f "$report" ]; then
    load="$(awk -F, -v r="$row" 'NR == r {printf "%.4g", $2}' "$report")"
  else
    load="$(awk -F' = ' '/^nip_load_P_N_per_mm/ {printf "%.3g", $2}' "$nip/contact.txt")"
  fi
  plots+="'$nip/outer_surface.csv' using 5:(\$8 > 0 ? \$8 : 1/0) with lines lw 2 lc $colour title 'roll, P = $load $unit', "
  plots+="'$nip/mating_roll/outer_surface.csv' using (abs(\$5)):(\$8 > 0 ? \$8 : 1/0) with points pt 6 ps 0.8 lc $colour title 'mating roll', "
  colour=$((colour + 1))
done
xmax="$(awk -F, 'NR > 1 && $8 > 0 && $5 > m {m = $5} END {printf "%.3g", 1.3 * m}' "$last/outer_surface.csv")"
gnuplot -e "set datafile separator ','; set terminal pngcairo enhanced font 'Sans,11' size 900,560; \
  set output '${prefix}_pressure.png'; set key top right; set grid; \
  set title 'Contact pressure on both rolls (lines: the roll, circles: the mating roll)'; \
  set xlabel 'deformed contact coordinate x_2 [mm]'; set ylabel 'contact pressure f [MPa]'; \
  set xrange [0:$xmax]; plot ${plots%, }"

# The two deformed surfaces of the last nip, and their undeformed circles.
x_roll="$(awk -F, 'NR == 2 {print $4}' "$last/outer_surface.csv")"
x_mate="$(awk -F, 'NR == 2 {print $4}' "$last/mating_roll/outer_surface.csv")"
R0="$(awk -F, 'NR == 2 {print $2}' "$last/outer_surface.csv")"
R0m="$(awk -F, 'NR == 2 {print $2}' "$last/mating_roll/outer_surface.csv")"
D="$(awk -v a="$x_roll" -v b="$x_mate" 'BEGIN {print a + b}')"
ymax="$(awk -v x="$xmax" 'BEGIN {print 1.5 * x}')"
x1min="$(awk -v x="$x_roll" 'BEGIN {print x - 6}')"
x1max="$(awk -v x="$x_roll" 'BEGIN {print x + 6}')"
gnuplot -e "set datafile separator ','; set terminal pngcairo enhanced font 'Sans,11' size 900,560; \
  set output '${prefix}_profiles.png'; set key top center; set grid; \
  set title 'Deformed surfaces of the last nip (dashed: undeformed, centres at their deformed distance)'; \
  set xlabel 'x_1 along the line of centres [mm]'; set ylabel 'x_2 [mm]'; \
  set xrange [$x1min:$x1max]; set yrange [0:$ymax]; set samples 400; set parametric; set trange [0:$ymax]; \
  plot '$last/outer_surface.csv' using 4:5 with lines lw 2 lc 1 title 'roll', \
       '$last/mating_roll/outer_surface.csv' using ($D - \$4):(abs(\$5)) with lines lw 2 lc 2 title 'mating roll', \
       sqrt($R0**2 - t**2), t with lines dt 2 lc 1 notitle, \
       $D - sqrt($R0m**2 - t**2), t with lines dt 2 lc 2 notitle"
echo "$me: wrote ${prefix}_pressure.png and ${prefix}_profiles.png"
