#!/usr/bin/env bash
# Plots the CSV tables of one rollnip run with gnuplot: PNG and SVG files in
# OUTPUT_DIR/plots/.
#
# Usage: bash scripts/plot_results.sh OUTPUT_DIR
#   e.g. bash scripts/plot_results.sh output/batra1980
#
# OUTPUT_DIR is the run's `Output/Directory`. Both layouts are understood:
#   - a sweep (several `Contact/Values`): OUTPUT_DIR/nip_characteristic.csv
#     with one row per nip and the nip's tables in OUTPUT_DIR/nip-01/, ...;
#   - a single nip or a run without contact: the tables in OUTPUT_DIR itself.
# A nip's linear-theory tables (OUTPUT_DIR/.../linear/) are drawn when present.
#
# Every nip is labelled by its load in the run's unit (nip_report.csv), and
# lengths and stresses are drawn in mm and MPa, or in inches and psi when the
# load is in pli (the unit of each CSV column is read from its header).
#
# Figures (NAME.png and NAME.svg):
#   contact_pressure             the contact pressure f(theta), surface nodes
#                                marked, nonlinear and small-strain (linear) theory
#   contact_pressure_normalised  the same, f / peak f against x2 / b (deformed nip
#                                coordinate over half-chord) with the Hertz shape;
#                                prints each curve's largest departure from it
#   contact_pressure_over_E      f / E against theta, only if ROLLNIP_E_MPA is set
#   nip_pressure                 the contact pressure and the normal stress of the
#                                cover at its surface (the check) across the nip
#   bond_stresses                sigma_rr and sigma_rtheta on the bond surface, nonlinear and linear
#   bond_stress_decay            |sigma_rr| and |sigma_rtheta| on the bond surface over
#                                their peaks, logarithmic (the truncation check)
#   deformed_surface[_nip-NN]    deformed and undeformed outer surface with the
#                                indenter, near the nip, equal scales
#   nip_characteristic           nip width 2b against the line load P, linear axes:
#                                nonlinear, linear theory (at its own b), Hertz, and
#                                the thin-layer asymptote where b/h >= 4 (its range)
#   nip_report                   nip width 2b and peak and mean pressure against the
#                                line load in the run's unit, linear axes (nip_report.csv)
#   indentation                  the indentation u0 against the line load, with its
#                                estimated error (nip_report.csv)
# A figure whose tables are missing (e.g. no contact) is skipped with a note.
#
# Environment:
#   ROLLNIP_E_MPA  Young's modulus E = 6 (C1 + C2) in MPa (the prm's Material
#                  section); when set, contact_pressure_over_E is drawn too.
#   ROLLNIP_UNITS  SI (mm, MPa) or US (in, psi); default: US when the load is
#                  in pli or lbf, else SI.
set -euo pipefail

me="plot_results"
die() {
  echo "$me: error: $*" >&2
  exit 1
}
note() { echo "$me: $*"; }

[ "$#" -eq 1 ] || die "usage: bash scripts/plot_results.sh OUTPUT_DIR"
outdir="${1%/}"
[ -d "$outdir" ] || die "'$outdir' is not a directory"
command -v gnuplot >/dev/null 2>&1 ||
  die "gnuplot not found; install the Debian package gnuplot-nox (bash scripts/setup.sh does)"
[ -n "$(find "$outdir" -maxdepth 2 -name '*.csv' -print -quit)" ] ||
  die "no CSV files in '$outdir'; run rollnip on a parameter file first"

# ---------------------------------------------------------------- terminals
terminals="$(gnuplot -e 'set terminal' </dev/null 2>&1 || true)"
has_terminal() { printf '%s\n' "$terminals" | grep -Eq "^[[:space:]]*$1[[:space:]]"; }
# Dashed curves (linear theory) carry open squares too where the terminal
# cannot dash (libgd png), so that they stay distinguishable.
dashed="lines"
lin_word="dashed"
if has_terminal pngcairo; then
  png_terminal="pngcairo enhanced font 'Sans,11'"
elif has_terminal png; then
  png_terminal="png enhanced font 'Sans,10'"
  dashed="linespoints pt 4 ps 1.3 pi 3"
  lin_word="squares"
  note "pngcairo is missing; using gnuplot's libgd png terminal"
else
  die "gnuplot has neither the pngcairo nor the png terminal"
fi
if has_terminal svg; then
  svg_terminal="svg enhanced font 'Sans,11' background '#ffffff'"
else
  svg_terminal=""
  note "gnuplot has no svg terminal; writing PNG only"
fi

if [ -n "${ROLLNIP_E_MPA:-}" ]; then
  awk -v e="$ROLLNIP_E_MPA" 'BEGIN { exit !(e ~ /^[0-9.]+([eE][-+]?[0-9]+)?$/ && e + 0 > 0) }' ||
    die "ROLLNIP_E_MPA must be a positive number (Young's modulus in MPa), not '$ROLLNIP_E_MPA'"
fi

plotdir="$outdir/plots"
mkdir -p "$plotdir"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# A file name as a gnuplot string literal (single quotes, '' inside).
gq() { printf "'%s'" "${1//\'/\'\'}"; }

# render NAME WIDTH HEIGHT: the gnuplot commands on stdin, drawn into
# NAME.png (and NAME.svg) in the plot directory.
written=()
render() {
  local name="$1" width="$2" height="$3"
  cat >"$tmp/$name.gp"
  local common="set encoding utf8; set datafile separator comma;"
  if ! gnuplot -e "$common set terminal $png_terminal size $width,$height; \
                   set output $(gq "$plotdir/$name.png")" "$tmp/$name.gp"; then
    cp "$tmp/$name.gp" "$plotdir/$name.gp"
    die "gnuplot failed on $name.png (its commands are in $plotdir/$name.gp)"
  fi
  if [ -n "$svg_terminal" ]; then
    if ! gnuplot -e "$common set terminal $svg_terminal size $width,$height; \
                     set output $(gq "$plotdir/$name.svg")" "$tmp/$name.gp"; then
      cp "$tmp/$name.gp" "$plotdir/$name.gp"
      die "gnuplot failed on $name.svg (its commands are in $plotdir/$name.gp)"
    fi
  fi
  written+=("$name")
}

# join SEPARATOR ITEMS...
join() {
  local sep="$1" out="" item
  shift
  for item in "$@"; do out="${out:+$out$sep}$item"; done
  printf '%s' "$out"
}

# Column number of a header name in a CSV file (empty if absent).
column_of() {
  head -n 1 "$1" | tr -d '\r' | tr ',' '\n' | awk -v n="$2" '$0 == n { print NR; exit }'
}

# Largest value of a CSV column (by number), and of its absolute value.
column_max() { awk -F, -v c="$2" 'NR > 1 && (m == "" || $c + 0 > m) { m = $c + 0 } END { print m }' "$1"; }
column_absmax() {
  awk -F, -v c="$2" 'NR > 1 { v = $c < 0 ? -$c : $c; if (v > m) m = v } END { print m + 0 }' "$1"
}

# A "key = value" entry of a rollnip text file (contact.txt, summary.txt).
entry() { [ -f "$1" ] && awk -F'[[:space:]]*=[[:space:]]*' -v k="$2" '$1 == k { print $2; exit }' "$1"; }

# ---------------------------------------------------------------- layout
characteristic="$outdir/nip_characteristic.csv"
n_rows=0
if [ -f "$characteristic" ]; then
  n_rows=$(($(grep -c . "$characteristic") - 1))
fi

nips=()
if [ "$n_rows" -gt 1 ]; then
  for ((i = 1; i <= n_rows; ++i)); do
    d="$outdir/$(printf 'nip-%02d' "$i")"
    [ -d "$d" ] || die "'$characteristic' has $n_rows nips but '$d' is missing"
    nips+=("$d")
  done
  extra="$(printf 'nip-%02d' $((n_rows + 1)))"
  [ -d "$outdir/$extra" ] &&
    note "ignoring $outdir/$extra and beyond: not in nip_characteristic.csv (an older run?)"
elif [ -f "$outdir/outer_surface.csv" ] || [ -f "$outdir/bond_surface.csv" ]; then
  nips=("$outdir")
  [ -d "$outdir/nip-01" ] &&
    note "using the tables in $outdir itself; ignoring nip-NN/ (an older sweep?)"
else
  for d in "$outdir"/nip-[0-9][0-9]; do
    [ -d "$d" ] && nips+=("$d")
  done
fi
[ "${#nips[@]}" -gt 0 ] || die "no outer_surface.csv or bond_surface.csv in '$outdir' or its nip-NN/"
single=$([ "${#nips[@]}" -eq 1 ] && [ "${nips[0]}" = "$outdir" ] && echo 1 || echo 0)

# ---------------------------------------------------------------- units
# The load as the user gave it: the second column of nip_report.csv names its
# unit (line_load_kN_per_m, line_load_pli, total_force_kN, ...).
report="$outdir/nip_report.csv"
load_name=""
[ -f "$report" ] && load_name="$(head -n 1 "$report" | tr -d '\r' | cut -d, -f2)"
load_unit="$(printf '%s' "${load_name#*_load_}" | sed 's/^total_force_//; s/_per_/\//')"
load_symbol="P"
[[ "$load_name" == total_force_* ]] && load_symbol="F"
[ -n "$load_name" ] || load_unit="N/mm"
units="${ROLLNIP_UNITS:-}"
if [ -z "$units" ]; then
  case "$load_unit" in pli | lbf* | lb*) units=US ;; *) units=SI ;; esac
fi
case "$units" in
  SI) len_unit="mm" p_unit="MPa" ;;
  US) len_unit="in" p_unit="psi" ;;
  *) die "ROLLNIP_UNITS must be SI or US, not '$units'" ;;
esac
# factor FILE COLUMN: the factor from the unit of the column (the end of its
# header name: _mm, _in, _MPa, _psi) to the unit of the plots.
factor() {
  local h
  h="$(head -n 1 "$1" | tr -d '\r' | cut -d, -f"$2")"
  case "$units:$h" in
    US:*_mm) echo 0.03937007874 ;;
    US:*_MPa) echo 145.0377377 ;;
    SI:*_in) echo 25.4 ;;
    SI:*_psi) echo 0.006894757293 ;;
    *) echo 1 ;;
  esac
}
# The factor of a value in mm or MPa (contact.txt) to the plots' unit.
mm_factor="$( [ "$units" = US ] && echo 0.03937007874 || echo 1)"

# Per nip: label, theta0, colour.
colours=("#1f77b4" "#d62728" "#2ca02c" "#9467bd" "#ff7f0e" "#8c564b" "#17becf" "#7f7f7f")
labels=()    # for gnuplot (enhanced text)
names=()     # for the screen
theta0s=()
for i in "${!nips[@]}"; do
  d="${nips[$i]}"
  t0="$(entry "$d/contact.txt" half_nip_angle_theta0_deg || true)"
  theta0s+=("$t0")
  # The nip's load in the user's unit: row i of nip_report.csv.
  load=""
  [ -n "$load_name" ] && load="$(awk -F, -v r=$((i + 2)) 'NR == r { printf "%.4g", $2 }' "$report")"
  if [ -n "$load" ]; then
    labels+=("$load_symbol = $load $load_unit")
    names+=("$load_symbol=$load${load_unit// /}")
  elif [ -n "$t0" ]; then
    t0="$(awk -v t="$t0" 'BEGIN { printf "%.4g", t }')"
    labels+=("θ_0 = $t0°")
    names+=("theta0=$t0")
  else
    l="$(basename "$d")"
    labels+=("${l//_/\\_}")
    names+=("$l")
  fi
done
colour() { printf '%s' "${colours[$(($1 % ${#colours[@]}))]}"; }

note "${#nips[@]} nip(s) in $outdir: ${names[*]}"

# ---------------------------------------------------------------- a. f(theta)
# contact_pressure.csv holds f at its knots only. Between them the program's
# f is linear, except on the last segment, up to theta0, where it falls like
# the square root of the distance to theta0 (source/contact/inverse_contact.cc).
# dense_pressure KNOTS_CSV OUTER_SURFACE_CSV OUT writes that f finely sampled,
# as "theta_deg,x2_mm,f_MPa", with x2 (the deformed nip coordinate)
# interpolated in theta between the surface nodes; OUT.ext is the same with
# f = 0 continued to the last surface node.
dense_pressure() {
  awk -F, -v out="$3" '
    FNR == 1 { ++file; next }
    file == 1 { n++; th[n] = $1 + 0; y[n] = $5 + 0; next }
    file == 2 { m++; t[m] = $1 + 0; f[m] = $2 + 0 }
    function x2(a,   k) {
      for (k = 1; k < n - 1 && th[k + 1] < a; ++k) {}
      return y[k] + (y[k + 1] - y[k]) * (a - th[k]) / (th[k + 1] - th[k])
    }
    END {
      S = 12
      print "theta_deg,x2_mm,f_MPa" > out
      for (k = 1; k < m; ++k)
        for (s = 0; s < S; ++s) {
          if (k == m - 1) {          # square-root fall, sampled in even steps of f
            w = 1 - s / S; a = t[m] - (t[m] - t[k]) * w * w; v = f[k] * w
          } else {
            a = t[k] + (t[k + 1] - t[k]) * s / S; v = f[k] + (f[k + 1] - f[k]) * s / S
          }
          print a "," x2(a) "," v > out
        }
      print t[m] "," x2(t[m]) "," f[m] > out
      close(out)
      while ((getline line < out) > 0) print line > (out ".ext")
      print th[n] "," y[n] ",0" > (out ".ext")
    }' "$2" "$1"
}

curves=()
curves_n=()
curves_e=()
dense=() # per nip: the dense nonlinear f, or empty
have_linear=0
for i in "${!nips[@]}"; do
  d="${nips[$i]}"
  dense+=("")
  if [ ! -f "$d/contact_pressure.csv" ] || [ ! -f "$d/outer_surface.csv" ]; then
    continue
  fi
  c="$(colour "$i")"
  for theory in nonlinear linear; do
    if [ "$theory" = nonlinear ]; then
      src="$d"
      style="lines lw 2"
      knots="points pt 7 ps 0.6"
      name="${labels[$i]}"
    else
      src="$d/linear"
      style="$dashed lw 2 dt 2"
      knots="points pt 6 ps 0.6"
      name="${labels[$i]}: small-strain theory, same contact edge"
    fi
    if [ ! -f "$src/contact_pressure.csv" ] || [ ! -f "$src/outer_surface.csv" ]; then
      continue
    fi
    df="$tmp/f_${i}_$theory.csv"
    dense_pressure "$src/contact_pressure.csv" "$src/outer_surface.csv" "$df"
    if [ "$theory" = nonlinear ]; then dense[i]="$df"; else have_linear=1; fi
    pk="$(column_max "$src/contact_pressure.csv" 2)"
    # b: the deformed half-chord, x2 at theta0 (the last sample).
    b="$(awk -F, 'END { print $2 }' "$df")"
    dq="$(gq "$df")"
    kq="$(gq "$src/contact_pressure.csv")"
    fp="$(factor "$src/contact_pressure.csv" 2)"
    title="title '$name'"
    curves+=("$dq skip 1 using 1:(column(3)*$fp) with $style lc rgb '$c' $title"
      "$kq skip 1 using 1:(column(2)*$fp) with $knots lc rgb '$c' notitle")
    curves_n+=("$dq skip 1 using (column(2)/$b):(column(3)/$pk) with $style lc rgb '$c' $title")
    # The largest departure of f/f_peak from the Hertz shape sqrt(1 - (x2/b)^2).
    awk -F, -v b="$b" -v pk="$pk" -v name="$theory, ${names[$i]}" '
      NR > 1 { s = $2 / b; d = $3 / pk - sqrt(s < 1 ? 1 - s * s : 0)
               if (d < lo) { lo = d; at_lo = s }; if (d > hi) { hi = d; at_hi = s } }
      END { printf "plot_results: %s: f/f_peak - sqrt(1 - (x2/b)^2) from %+.1f %% (x2/b = %.2f) to %+.1f %% (x2/b = %.2f) of the peak; b = %.4f mm\n",
                   name, 100 * lo, at_lo, 100 * hi, at_hi, b }' "$df"
    if [ -n "${ROLLNIP_E_MPA:-}" ]; then
      curves_e+=("$dq skip 1 using 1:(column(3)/$ROLLNIP_E_MPA) with $style lc rgb '$c' $title"
        "$kq skip 1 using 1:(column(2)/$ROLLNIP_E_MPA) with $knots lc rgb '$c' notitle")
    fi
  done
done
if [ "${#curves[@]}" -gt 0 ]; then
  theories="solid: finite strain, $lin_word: small-strain theory"
  [ "$have_linear" -eq 1 ] || theories="finite strain"
  render contact_pressure 900 620 <<EOF
set title 'Contact pressure ($theories; symbols: surface nodes)'
set xlabel 'angle θ from the line of centres, undeformed roll (deg)'
set ylabel 'contact pressure f ($p_unit)'
set grid
set key top right box opaque
set xrange [0:*]
set yrange [0:*]
plot $(join ", " "${curves[@]}")
EOF
  render contact_pressure_normalised 900 620 <<EOF
set title 'Contact pressure over its peak against the deformed nip coordinate, and Hertz'
set xlabel 'x_2 / b (deformed nip coordinate over deformed half-chord, dimensionless)'
set ylabel 'f / f_{peak} (dimensionless)'
set grid
set key bottom left box opaque
set xrange [0:1]
set yrange [0:1.05]
set samples 400
plot $(join ", " "${curves_n[@]}"), \\
     sqrt(1 - x**2) with lines lw 1 lc rgb '#000000' title 'Hertz shape √(1 - (x_2/b)^2)'
EOF
  if [ "${#curves_e[@]}" -gt 0 ]; then
    render contact_pressure_over_E 900 620 <<EOF
set title 'Contact pressure over E = $ROLLNIP_E_MPA MPa ($theories; symbols: surface nodes)'
set xlabel 'angle θ from the line of centres, undeformed roll (deg)'
set ylabel 'f / E (dimensionless; E = 6 (C_1 + C_2) = $ROLLNIP_E_MPA MPa)'
set grid
set key top right box opaque
set xrange [0:*]
set yrange [0:*]
plot $(join ", " "${curves_e[@]}")
EOF
  fi
else
  note "skipping contact_pressure: no contact_pressure.csv"
fi

# ------------------------------------------- b. f and normal traction vs x2
# Half-width of the loaded zone on the deformed surface: y of the first node
# past the loaded ones (used for zooming).
loaded_half_width() {
  awk -F, 'NR > 1 { if ($8 + 0 > 0) seen = 1; else if (seen) { print $5; exit } }' "$1"
}
curves=()
bmax=0
pmax=0
for i in "${!nips[@]}"; do
  f="${nips[$i]}/outer_surface.csv"
  [ -f "$f" ] || continue
  b="$(loaded_half_width "$f")"
  [ -n "$b" ] && bmax="$(awk -v a="$bmax" -v b="$b" 'BEGIN { print (b > a ? b : a) }')"
  pmax="$(awk -F, -v m="$pmax" 'NR > 1 { if ($8 + 0 > m) m = $8 + 0; if ($9 + 0 > m) m = $9 + 0 } END { print m }' "$f")"
  c="$(colour "$i")"
  fx="$(factor "$f" 5)"
  fs="$(factor "$f" 9)"
  fa="$(factor "$f" 8)"
  if [ -n "${dense[i]:-}" ]; then
    # f as the program represents it (see dense_pressure), zero beyond theta0.
    fq="$(gq "${dense[i]}.ext")"
  else
    # No knots (a prescribed pressure): f at the surface nodes.
    fq="$(gq "$tmp/nodal_f_$i.csv")"
    awk -F, 'NR == 1 { print "theta_deg,x2_mm,f_MPa"; next } { print $1 "," $5 "," $8 }' "$f" >"$tmp/nodal_f_$i.csv"
  fi
  curves+=("$fq skip 1 using (column(2)*$fx):(column(3)*$fa) with lines lw 2 lc rgb '$c' title 'contact pressure, ${labels[$i]}'"
    "$fq skip 1 using (-column(2)*$fx):(column(3)*$fa) with lines lw 2 lc rgb '$c' notitle"
    "$(gq "$f") skip 1 using (column(5)*$fx):(column(9)*$fs) with points pt 6 ps 0.9 lc rgb '$c' title 'normal stress at the surface, ${labels[$i]}'"
    "$(gq "$f") skip 1 using (-column(5)*$fx):(column(9)*$fs) with points pt 6 ps 0.9 lc rgb '$c' notitle")
done
if [ "${#curves[@]}" -gt 0 ]; then
  if awk -v b="$bmax" 'BEGIN { exit !(b > 0) }'; then
    xr="$(awk -v b="$bmax" -v s="$fx" 'BEGIN { printf "[%g:%g]", -1.6 * b * s, 1.6 * b * s }')"
  else
    xr="[*:*]"
  fi
  yr="$(awk -v p="$pmax" -v s="$fa" 'BEGIN { if (p > 0) printf "[%g:%g]", -0.05 * p * s, 1.12 * p * s; else print "[*:*]" }')"
  render nip_pressure 900 620 <<EOF
set title 'Pressure across the nip (lines: contact pressure; circles: normal stress at the surface, a check)'
set xlabel 'position across the nip, deformed surface ($len_unit)'
set ylabel 'pressure ($p_unit)'
set grid
set key top right box opaque font ',9'
set xrange $xr
set yrange $yr
plot $(join ", " "${curves[@]}")
EOF
else
  note "skipping nip_pressure: no outer_surface.csv"
fi

# ------------------------------------------------- c. bond-surface stresses
rr=()
rt=()
decay=()
theories="finite strain"
for i in "${!nips[@]}"; do
  d="${nips[$i]}"
  f="$d/bond_surface.csv"
  [ -f "$f" ] || continue
  c="$(colour "$i")"
  f2="$(factor "$f" 2)"
  f3="$(factor "$f" 3)"
  rr+=("$(gq "$f") skip 1 using 1:(column(2)*$f2) with lines lw 2 lc rgb '$c' title '${labels[$i]}'")
  rt+=("$(gq "$f") skip 1 using 1:(column(3)*$f3) with lines lw 2 lc rgb '$c' title '${labels[$i]}'")
  m2="$(column_absmax "$f" 2)"
  m3="$(column_absmax "$f" 3)"
  decay+=("$(gq "$f") skip 1 using 1:(abs(column(2))/$m2) with lines lw 2 lc rgb '$c' title '|σ_{rr}|, ${labels[$i]}'")
  decay+=("$(gq "$f") skip 1 using 1:(abs(column(3))/$m3) with $dashed lw 1.5 dt 2 lc rgb '$c' title '|σ_{rθ}|, ${labels[$i]}'")
  fl="$d/linear/bond_surface.csv"
  if [ -f "$fl" ]; then
    theories="solid: finite strain, $lin_word: small-strain theory"
    rr+=("$(gq "$fl") skip 1 using 1:(column(2)*$f2) with $dashed lw 2 dt 2 lc rgb '$c' title '${labels[$i]}, small strain'")
    rt+=("$(gq "$fl") skip 1 using 1:(column(3)*$f3) with $dashed lw 2 dt 2 lc rgb '$c' title '${labels[$i]}, small strain'")
  fi
done
if [ "${#rr[@]}" -gt 0 ]; then
  render bond_stresses 900 900 <<EOF
set multiplot layout 2,1 title 'Cauchy stresses on the bond surface r = R_1 ($theories)'
set grid
set xrange [0:*]
set xlabel 'angle θ from the line of centres, undeformed roll (deg)'
set key bottom right box opaque font ',9'
set ylabel 'radial stress σ_{rr} ($p_unit)'
plot $(join ", " "${rr[@]}")
set key top right box opaque font ',9'
set ylabel 'shear stress σ_{rθ} ($p_unit)'
plot $(join ", " "${rt[@]}")
unset multiplot
EOF
  render bond_stress_decay 900 620 <<EOF
set title 'Decay of the bond stresses away from the nip'
set xlabel 'angle θ from the line of centres, undeformed roll (deg)'
set ylabel '|stress| / its peak on the bond surface (dimensionless)'
set logscale y
set format y '10^{%T}'
set yrange [1e-4:1.5]
set xrange [0:*]
set grid
set key top right box opaque font ',9'
set arrow from graph 0, first 0.01 to graph 1, first 0.01 nohead dt 4 lc rgb '#555555'
set label '1 %' at graph 0.01, first 0.013 tc rgb '#555555'
plot $(join ", " "${decay[@]}")
EOF
else
  note "skipping bond_stresses: no bond_surface.csv"
fi

# --------------------------------------------------- d. the deformed surface
for i in "${!nips[@]}"; do
  d="${nips[$i]}"
  f="$d/outer_surface.csv"
  [ -f "$f" ] || continue
  b="$(loaded_half_width "$f")"
  if [ -z "$b" ]; then
    note "skipping deformed_surface for $d: no loaded zone in outer_surface.csv"
    continue
  fi
  name="deformed_surface"
  [ "$single" -eq 1 ] || name="deformed_surface_$(basename "$d")"
  # Centre of the view: the deformed surface point on the line of centres.
  xc="$(awk -F, 'NR == 2 { print $4 }' "$f")"
  fl="$(factor "$f" 4)"
  read -r xr yr <<<"$(awk -v b="$b" -v xc="$xc" -v s="$fl" 'BEGIN {
      w = 2.2 * b; v = 0.36 * w
      printf "[%g:%g] [%g:%g]\n", -w * s, w * s, (xc - v) * s, (xc + v) * s }')"
  u0="$(entry "$d/contact.txt" indentation_u0_mm || true)"
  title="Outer surface near the nip, ${labels[$i]}"
  [ -n "$u0" ] && title="$title, indentation u_0 = $(awk -v u="$u0" -v s="$mm_factor" 'BEGIN { printf "%.4g", u * s }') $len_unit"
  s="*$fl"
  curves=(
    "$(gq "$f") skip 1 using (column(3)$s):(column(2)$s) with lines lw 1.5 dt 2 lc rgb '#777777' title 'undeformed surface'"
    "$(gq "$f") skip 1 using (-column(3)$s):(column(2)$s) with lines lw 1.5 dt 2 lc rgb '#777777' notitle"
    "$(gq "$f") skip 1 using (column(5)$s):(column(4)$s) with linespoints lw 2 pt 7 ps 0.4 lc rgb '#1f77b4' title 'deformed surface (nodes)'"
    "$(gq "$f") skip 1 using (-column(5)$s):(column(4)$s) with linespoints lw 2 pt 7 ps 0.4 lc rgb '#1f77b4' notitle"
  )
  if [ -f "$d/indenter.csv" ]; then
    si="*$(factor "$d/indenter.csv" 1)"
    curves+=(
      "$(gq "$d/indenter.csv") skip 1 using (column(2)$si):(column(1)$si) with lines lw 2 lc rgb '#d62728' title 'mating roll'"
      "$(gq "$d/indenter.csv") skip 1 using (-column(2)$si):(column(1)$si) with lines lw 2 lc rgb '#d62728' notitle"
    )
  fi
  render "$name" 1000 520 <<EOF
set title '$title'
set xlabel 'across the nip ($len_unit)'
set ylabel 'along the line of centres, from the roll axis ($len_unit)'
set size ratio -1
set xrange $xr
set yrange $yr
set grid
set key top center box opaque font ',9' maxrows 2
plot $(join ", " "${curves[@]}")
EOF
done

# ------------------------------------------------ e. the nip characteristic
if [ -f "$characteristic" ] && [ "$n_rows" -ge 1 ]; then
  cb="$(column_of "$characteristic" half_chord_mm)"
  cp="$(column_of "$characteristic" P_N_per_mm)"
  cl="$(column_of "$characteristic" P_linear_N_per_mm)"
  ch="$(column_of "$characteristic" P_hertz_N_per_mm)"
  ct="$(column_of "$characteristic" P_thin_layer_N_per_mm)"
  cbh="$(column_of "$characteristic" half_chord_over_cover_thickness)"
  if [ -n "$cb" ] && [ -n "$cp" ]; then
    style="linespoints"
    [ "$n_rows" -gt 1 ] || style="points"
    fq="$(gq "$characteristic")"
    # Loads in the user's unit (the first row of nip_report.csv gives the
    # factor from N/mm), widths in the plots' length unit.
    lf=1
    if [ -n "$load_name" ]; then
      cn="$(column_of "$report" line_load_N_per_mm)"
      [ -n "$cn" ] && lf="$(awk -F, -v c="$cn" 'NR == 2 && $c + 0 > 0 { printf "%.12g", $2 / $c; exit }
                                                END { if (NR < 2) print 1 }' "$report")"
      [ -n "$lf" ] || lf=1
    fi
    wf="$(factor "$characteristic" "$cb")"
    w="(2*column($cb)*$wf)"
    # A column is drawn if present with some positive value (P_linear is 0
    # when the linear comparison was off).
    positive() {
      [ -n "$1" ] && awk -F, -v c="$1" 'NR > 1 && $c + 0 > 0 { found = 1 } END { exit !found }' "$characteristic"
    }
    # Each curve is (P, 2b): the load that its theory needs for the width 2b.
    curves=("$fq skip 1 using (column($cp)*$lf):$w with $style lw 2 pt 7 ps 1.2 lc rgb '#1f77b4' title 'rollnip (finite strain)'")
    if positive "$cl"; then
      # The linear theory at its own half-chord: x2 at theta0 on its deformed
      # surface, the last sample of its dense f (section a).
      linb="$tmp/linear_characteristic.csv"
      echo "half_chord_mm,P_linear_N_per_mm" >"$linb"
      for i in "${!nips[@]}"; do
        [ -f "$tmp/f_${i}_linear.csv" ] || continue
        b="$(awk -F, 'END { print $2 }' "$tmp/f_${i}_linear.csv")"
        awk -F, -v r=$((i + 2)) -v c="$cl" -v b="$b" 'NR == r { print b "," $c }' "$characteristic" >>"$linb"
      done
      if [ "$(grep -c . "$linb")" -gt 1 ]; then
        curves+=("$(gq "$linb") skip 1 using (column(2)*$lf):(2*column(1)*$wf) with $style lw 2 dt 2 pt 5 ps 1.1 lc rgb '#d62728' title 'rollnip, small-strain theory'")
      else
        curves+=("$fq skip 1 using (column($cl)*$lf):$w with $style lw 2 dt 2 pt 5 ps 1.1 lc rgb '#d62728' title 'rollnip, small-strain theory'")
      fi
    fi
    positive "$ch" && curves+=("$fq skip 1 using (column($ch)*$lf):$w with $style lw 1.5 dt 4 pt 9 ps 1.2 lc rgb '#2ca02c' title 'Hertz, incompressible half-space'")
    # The thin-layer asymptote holds for b >> h only (several times too low
    # at b/h = 4, still 25 % at 32): drawn where b/h >= 4, else left out.
    if [ -n "$ct" ] && [ -n "$cbh" ] &&
      awk -F, -v c="$cbh" 'NR > 1 && $c + 0 >= 4 { found = 1 } END { exit !found }' "$characteristic"; then
      curves+=("$fq skip 1 using (column($cbh) >= 4 ? column($ct)*$lf : 1/0):$w with $style lw 1.5 dt 5 pt 11 ps 1.2 lc rgb '#9467bd' title 'thin bonded layer asymptote (b/h ≥ 4)'")
    else
      note "nip_characteristic: no nip has b/h >= 4, the thin-layer asymptote is not drawn"
    fi
    render nip_characteristic 900 620 <<EOF
set title 'Nip characteristic: nip width against line load'
set xlabel '$( [ "$load_symbol" = F ] && echo "total force F" || echo "line load P") ($load_unit)'
set ylabel 'full nip width 2b, deformed ($len_unit)'
set xrange [0:*]
set yrange [0:*]
set grid
set key bottom right box opaque
plot $(join ", " "${curves[@]}")
EOF
  else
    note "skipping nip_characteristic: no half_chord_mm or P_N_per_mm column"
  fi
else
  note "skipping nip_characteristic: no nip_characteristic.csv, or no rows in it"
fi

# ------------------------------------------------------- f. the nip report
# report_column PREFIX: the column of nip_report.csv named PREFIX_<unit>
# (not an error column), preferring the plots' unit when there are several.
report_column() {
  head -n 1 "$report" | tr -d '\r' | tr ',' '\n' | awk -v p="$1_" -v u="$units" '
    index($0, p) == 1 && $0 !~ /_err_/ {
      unit = substr($0, length(p) + 1)
      us = unit ~ /^(in|psi|fpm|pli)$/
      if (first == "") first = NR
      if ((u == "US") == us && mine == "") mine = NR
    }
    END { print (mine != "" ? mine : first) }'
}
if [ -f "$report" ] && [ "$(grep -c . "$report")" -ge 2 ]; then
  load_label="$( [ "$load_symbol" = F ] && echo "total force" || echo "line load") ($load_unit)"
  cw="$(report_column nip_width_2b)"
  cpk="$(report_column peak_pressure)"
  cmn="$(report_column mean_pressure)"
  cu="$(report_column indentation_u0)"
  style="linespoints"
  [ "$(grep -c . "$report")" -gt 2 ] || style="points"
  fq="$(gq "$report")"
  w="(column($cw)*$(factor "$report" "$cw"))"
  pk="(column($cpk)*$(factor "$report" "$cpk"))"
  mn="(column($cmn)*$(factor "$report" "$cmn"))"
  render nip_report 900 620 <<EOF
set title 'Nip report: nip width and pressure against $( [ "$load_symbol" = F ] && echo "total force" || echo "line load")'
set xlabel '$load_label'
set ylabel 'nip width 2b, deformed ($len_unit)'
set y2label 'pressure ($p_unit)'
set xrange [0:*]
set yrange [0:*]
set y2range [0:*]
set ytics nomirror
set y2tics
set grid
set key top left box opaque
plot $fq skip 1 using 2:$w with $style lw 2 pt 7 lc rgb '#1f77b4' title 'nip width 2b (left axis)', \\
     $fq skip 1 using 2:$pk axes x1y2 with $style lw 2 dt 2 pt 5 lc rgb '#d62728' title 'peak pressure (right axis)', \\
     $fq skip 1 using 2:$mn axes x1y2 with $style lw 1.5 dt 4 pt 9 lc rgb '#2ca02c' title 'mean pressure P/2b (right axis)'
EOF
  if [ -n "$cu" ]; then
    fu="$(factor "$report" "$cu")"
    # The estimated error as an error bar, when the run estimated it.
    ce="$(head -n 1 "$report" | tr -d '\r' | tr ',' '\n' | awk '/^indentation_u0_err_/ { print NR; exit }')"
    if [ -n "$ce" ]; then
      fe="$(factor "$report" "$ce")"
      bars="$fq skip 1 using 2:(column($cu)*$fu):(column($ce)*$fe) with yerrorbars pt 7 ps 0.8 lc rgb '#1f77b4' title 'estimated error (mesh)', "
    else
      bars=""
    fi
    render indentation 900 620 <<EOF
set title 'Indentation against $( [ "$load_symbol" = F ] && echo "total force" || echo "line load")'
set xlabel '$load_label'
set ylabel 'indentation u_0, approach of the roll axes ($len_unit)'
set xrange [0:*]
set yrange [0:*]
set grid
set key top left box opaque
plot ${bars}$fq skip 1 using 2:(column($cu)*$fu) with $style lw 2 pt 7 lc rgb '#1f77b4' title 'indentation u_0'
EOF
  fi
else
  note "skipping nip_report and indentation: no nip_report.csv, or no rows in it"
fi

[ "${#written[@]}" -gt 0 ] || die "nothing to plot in '$outdir'"
note "wrote ${#written[@]} figure(s) to $plotdir: $(join ", " "${written[@]}")"
