#!/usr/bin/env bash
# Plots the speed-accuracy front of a refinement study (Study/Refinement
# levels): the estimated relative error of the first quantity (P for a
# contact scene, u0 for a pressure scene) and, for contact, of the nip
# half-width b, against the wall time of each run, one curve per element
# (per nip and element for a study over a sweep, labelled by its load or
# other prescribed value), log-log. Writes OUTPUT_DIR/plots/study_front.png and .svg.
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
# One data file per nip (of a sweep) and variant, rows with a zero error
# dropped (log scale).
variant_col="$(col variant)"
[ -n "$variant_col" ] || die "'$csv' has no variant column"
nip_col="$(col nip || true)"
value_col=""
[ -n "$nip_col" ] && value_col=$((nip_col + 1))
value_name="$(printf '%s\n' "$header" | cut -d, -f"${value_col:-1}")"
value_name="${value_name#prescribed_}"
case "$value_name" in
  theta0_deg) value_label="theta0 = %s deg" ;;
  u0_mm) value_label="u0 = %s mm" ;;
  line_load_N_per_mm) value_label="P = %s N/mm" ;;
  line_load_kN_per_m) value_label="P = %s kN/m" ;;
  line_load_pli) value_label="P = %s pli" ;;
  total_force_kN) value_label="F = %s kN" ;;
  total_force_N) value_label="F = %s N" ;;
  *) value_label="%s" ;;
esac
n_nips=1
[ -n "$nip_col" ] && n_nips="$(tail -n +2 "$csv" | cut -d, -f"$nip_col" | sort -u | wc -l)"
plots=""
i=0
while IFS=, read -r key value variant; do
  i=$((i + 1))
  awk -F, -v n="$nip_col" -v k="$key" -v vc="$variant_col" -v v="$variant" \
    'NR > 1 && (n == "" || $n == k) && $vc == v' "$csv" >"$tmp/$i.dat"
  name="$variant"
  if [ "$n_nips" -gt 1 ]; then
    # shellcheck disable=SC2059
    name="$(printf "$value_label" "$value"), $variant"
  fi
  plots="$plots '$tmp/$i.dat' using $wall:(\$$e1 > 0 ? \$$e1 : 1/0) with linespoints lw 2 lc $i title '$name: $e1_name',"
  if [ -n "$e2" ]; then
    plots="$plots '$tmp/$i.dat' using $wall:(\$$e2 > 0 ? \$$e2 : 1/0) with linespoints dt 2 lw 2 lc $i title '$name: nip half-width b',"
  fi
done < <(tail -n +2 "$csv" | awk -F, -v n="$nip_col" -v val="$value_col" -v vc="$variant_col" \
  '{ key = n == "" ? "" : $n; value = val == "" ? "" : $val; k = key "," value "," $vc; if (!(k in seen)) { seen[k] = 1; print k } }')
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
