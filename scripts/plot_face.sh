#!/usr/bin/env bash
# Plots a face run (Face/Enabled = true, doc/face.md) from its face.csv:
# the line load q and the nip width 2b along the face, and the shapes that
# make them: the crown (on the radius), both cores' deflections and the
# local approach delta.
#
# Usage: bash scripts/plot_face.sh RUN_DIR [PNG_PREFIX]
# (RUN_DIR: the Output/Directory of the run). Writes PNG_PREFIX_loads.png
# and PNG_PREFIX_shapes.png (default prefix: RUN_DIR/face).
set -euo pipefail
me="plot_face.sh"
die() { echo "$me: $*" >&2; exit 1; }

[ "$#" -ge 1 ] || die "usage: bash scripts/plot_face.sh RUN_DIR [PNG_PREFIX]"
run="${1%/}"
prefix="${2:-$run/face}"
command -v gnuplot >/dev/null 2>&1 ||
  die "gnuplot not found; install the Debian package gnuplot-nox (bash scripts/setup.sh does)"
[ -f "$run/face.csv" ] || die "no face.csv in '$run': is it a face run (Face/Enabled = true)?"

gnuplot -e "set datafile separator ','; set terminal pngcairo enhanced font 'Sans,11' size 900,560; \
  set output '${prefix}_loads.png'; set key bottom center; set grid; \
  set title 'The nip along the face'; set xlabel 'y [mm] (0: face centre)'; \
  set ylabel 'line load q [N/mm]'; set y2label 'nip width 2b [mm]'; set ytics nomirror; set y2tics; \
  set yrange [0:*]; set y2range [0:*]; \
  plot '$run/face.csv' using 1:2 skip 1 with lines lw 2 title 'q', \
       '' using 1:3 skip 1 axes x1y2 with lines lw 2 dt 2 title '2b'"

gnuplot -e "set datafile separator ','; set terminal pngcairo enhanced font 'Sans,11' size 900,560; \
  set output '${prefix}_shapes.png'; set key center center; set grid; \
  set title 'Crown, deflections and the local approach'; set xlabel 'y [mm] (0: face centre)'; \
  set ylabel '[mm]'; \
  plot '$run/face.csv' using 1:10 skip 1 with lines lw 2 title 'crown (radius, both rolls)', \
       '' using 1:8 skip 1 with lines lw 2 title 'roll deflection', \
       '' using 1:9 skip 1 with lines lw 2 title 'mating roll deflection', \
       '' using 1:4 skip 1 with lines lw 2 dt 2 title 'approach {/Symbol d}'"
echo "$me: wrote ${prefix}_loads.png and ${prefix}_shapes.png"
