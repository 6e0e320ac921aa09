#!/usr/bin/env bash
# Plots a layered-cover nip sweep beside the same sweep on a one-layer cover:
# the contact pressure over the deformed contact coordinate for every nip,
# and the stresses on the interface and the bond of the last nip.
#
# Usage: bash scripts/plot_layers.sh LAYERED_DIR ONE_LAYER_DIR [PNG_PREFIX]
# (the Output/Directory of two runs with the same Contact/Values; doc/layers.md
# gives the commands). Writes PNG_PREFIX_pressure.png and
# PNG_PREFIX_interface.png (default prefix: LAYERED_DIR/layers).
set -euo pipefail
me="plot_layers.sh"
die() { echo "$me: $*" >&2; exit 1; }

[ "$#" -ge 2 ] || die "usage: bash scripts/plot_layers.sh LAYERED_DIR ONE_LAYER_DIR [PNG_PREFIX]"
layered="${1%/}"
single="${2%/}"
prefix="${3:-$layered/layers}"
command -v gnuplot >/dev/null 2>&1 ||
  die "gnuplot not found; install the Debian package gnuplot-nox (bash scripts/setup.sh does)"
nips=()
for d in "$layered"/nip-*/; do
  [ -f "$d/outer_surface.csv" ] && nips+=("$(basename "$d")")
done
[ "${#nips[@]}" -gt 0 ] || die "no nip-*/outer_surface.csv in '$layered'"
last="${nips[-1]}"
[ -f "$layered/$last/interface_1.csv" ] ||
  die "'$layered/$last' has no interface_1.csv: is it a layered cover?"

# Pressure on the contact zone, over the deformed coordinate y (x2), for
# every nip: solid layered, dashed one layer.
plots=""
colour=1
for nip in "${nips[@]}"; do
  load="$(awk -F' = ' '/^nip_load_P_N_per_mm/ {printf "%.3g", $2}' "$layered/$nip/contact.txt")"
  plots+="'$layered/$nip/outer_surface.csv' using 5:(\$9 > 0 ? \$9 : 1/0) with lines lw 2 lc $colour title 'layered, P = $load N/mm', "
  if [ -f "$single/$nip/outer_surface.csv" ]; then
    plots+="'$single/$nip/outer_surface.csv' using 5:(\$9 > 0 ? \$9 : 1/0) with lines lw 2 dt 2 lc $colour title 'one layer', "
  fi
  colour=$((colour + 1))
done
# The widest nip and a half beyond it.
xmax=""
if [ -f "$layered/nip_report.csv" ]; then
  xmax="$(awk -F, 'NR > 1 && $4 > m {m = $4} END {if (m > 0) printf "%.3g", 0.8 * m}' "$layered/nip_report.csv")"
fi
gnuplot -e "set datafile separator ','; set terminal pngcairo enhanced font 'Sans,11' size 900,560; \
  set output '${prefix}_pressure.png'; set key top right; set grid; \
  set xlabel 'deformed contact coordinate x_2 [mm]'; set ylabel 'normal pressure -{/Symbol s}_{nn} [MPa]'; \
  set xrange [0:${xmax:-*}]; plot ${plots%, }"

# Interface and bond stresses of the last nip over the reference angle.
gnuplot -e "set datafile separator ','; set terminal pngcairo enhanced font 'Sans,11' size 900,560; \
  set output '${prefix}_interface.png'; set key bottom right; set grid; \
  set xlabel 'reference angle {/Symbol Q} [deg]'; set ylabel 'stress [MPa]'; set xrange [0:40]; \
  plot '$layered/$last/interface_1.csv' using 1:2 with lines lw 2 lc 1 title 'interface {/Symbol s}_{nn}', \
       '' using 1:3 with lines lw 2 lc 2 title 'interface {/Symbol s}_{nt}', \
       '$layered/$last/bond_surface.csv' using 1:2 with lines lw 2 dt 2 lc 1 title 'bond {/Symbol s}_{rr}', \
       '' using 1:3 with lines lw 2 dt 2 lc 2 title 'bond {/Symbol s}_{r{/Symbol q}}', \
       '$single/$last/bond_surface.csv' using 1:2 with lines lw 1 dt 3 lc 1 title 'bond {/Symbol s}_{rr}, one layer', \
       '' using 1:3 with lines lw 1 dt 3 lc 2 title 'bond {/Symbol s}_{r{/Symbol q}}, one layer'"
echo "$me: wrote ${prefix}_pressure.png and ${prefix}_interface.png"
