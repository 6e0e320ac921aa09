#!/usr/bin/env bash
# Plots the speed-accuracy front of a refinement study (Study/Refinement
# levels): the estimated relative error of the first quantity (P for a
# contact scene, u0 for a pressure scene) and, for contact, of the nip
# half-width b, against the wall time of each run, one curve per element,
# log-log. Writes OUTPUT_DIR/plots/study_front.png and .svg.
#
# Usage: bash scripts/plot_study.sh OUTPUT_DIR     (the directory of study.csv)
set -euo pipefail

die() {
  echo "plot_study: error: $*" >&2
  exit 1
}
[ "$#" -eq 1 ] || die "usage: bash scripts/plot_study.sh OUTPUT_DIR"
outdir="${1%/}"
csv="$outdir/study.csv"
[ -f "$csv" ] || die "'$csv' not found; run rollnip with Study/Refinement levels set first"
command -v gnuplot >/dev/null 2>&1 ||
  die "gnuplot not found; install the Debian package gnuplot-nox (bash scripts/setup.sh does)"

header="$(head -n1 "$csv")"
col() { printf '%s\n' "$header" | tr ',' '\n' | grep -nx "$1" | cut -d: -f1; }
wall="$(col wall_s)"
[ -n "$wall" ] || die "'$csv' has no wall_s column"
first_error="$(printf '%s\n' "$header" | tr ',' '\n' | grep -n '^error_' | head -n1)"
[ -n "$first_error" ] || die "'$csv' has no error columns"
e1="${first_error%%:*}"
e1_name="${first_error#*:error_}"
e1_name="${e1_name%%_*}"
e2="$(col error_half_chord_mm || true)"

tmp="$(mktemp -d "${TMPDIR:-/tmp}/rollnip-study.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT
# One data file per element, rows with a zero error dropped (log scale).
elements="$(tail -n +2 "$csv" | cut -d, -f1 | sort -u)"
plots=""
for element in $elements; do
  awk -F, -v e="$element" 'NR > 1 && $1 == e' "$csv" >"$tmp/$element.dat"
  plots="$plots '$tmp/$element.dat' using $wall:(\$$e1 > 0 ? \$$e1 : 1/0) with linespoints lw 2 title '$element: $e1_name',"
  if [ -n "$e2" ]; then
    plots="$plots '$tmp/$element.dat' using $wall:(\$$e2 > 0 ? \$$e2 : 1/0) with linespoints dt 2 lw 2 title '$element: nip half-width b',"
  fi
done
plots="${plots%,}"

mkdir -p "$outdir/plots"
terminals="$(gnuplot -e 'set terminal' </dev/null 2>&1 || true)"
png="png"
printf '%s\n' "$terminals" | grep -Eq '^[[:space:]]*pngcairo[[:space:]]' && png="pngcairo"
common="set datafile separator ','; set logscale xy; set grid;
  set xlabel 'wall time per run [s]'; set ylabel 'estimated relative error';
  set format x '%g'; set format y '10^{%L}'; set key top right; set title 'Speed against accuracy (refinement study)';"
gnuplot -e "$common set terminal $png size 900,620; set output '$outdir/plots/study_front.png'; plot $plots" ||
  die "gnuplot failed on $csv"
if printf '%s\n' "$terminals" | grep -Eq '^[[:space:]]*svg[[:space:]]'; then
  gnuplot -e "$common set terminal svg size 900,620 background '#ffffff'; set output '$outdir/plots/study_front.svg'; plot $plots" ||
    die "gnuplot failed on $csv"
fi
echo "plot_study: wrote $outdir/plots/study_front.png"
