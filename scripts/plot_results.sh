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
# Figures (NAME.png and NAME.svg):
#   contact_pressure             f(theta), knots marked, nonlinear and linear
#   contact_pressure_normalised  the same, f / peak f against x2 / b (deformed nip
#                                coordinate over half-chord) with the Hertz shape;
#                                prints each curve's largest departure from it
#   contact_pressure_over_E      f / E against theta, only if ROLLNIP_E_MPA is set
#   nip_pressure                 imposed f and the normal traction from the stress
#                                against the deformed nip coordinate x2
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
# A figure whose tables are missing (e.g. no contact) is skipped with a note.
#
# Environment:
#   ROLLNIP_E_MPA  Young's modulus E = 6 (C1 + C2) in MPa (the prm's Material
#                  section); when set, contact_pressure_over_E is drawn too.
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

# Per nip: label, theta0, colour.
colours=("#1f77b4" "#d62728" "#2ca02c" "#9467bd" "#ff7f0e" "#8c564b" "#17becf" "#7f7f7f")
labels=()    # for gnuplot (enhanced text)
names=()     # for the screen
theta0s=()
for d in "${nips[@]}"; do
  t0="$(entry "$d/contact.txt" half_nip_angle_theta0_deg || true)"
  theta0s+=("$t0")
  if [ -n "$t0" ]; then
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
    else
      src="$d/linear"
      style="$dashed lw 2 dt 2"
      knots="points pt 6 ps 0.6"
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
    title="title '$theory, ${labels[$i]}'"
    curves+=("$dq skip 1 using 1:3 with $style lc rgb '$c' $title"
      "$kq skip 1 using 1:2 with $knots lc rgb '$c' notitle")
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
  theories="solid: nonlinear, $lin_word: linear theory"
  [ "$have_linear" -eq 1 ] || theories="nonlinear theory"
  render contact_pressure 900 620 <<EOF
set title 'Contact pressure f ($theories; symbols: knots)'
set xlabel 'reference angle θ (deg)'
set ylabel 'contact pressure f (MPa)'
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
set title 'Contact pressure over E = $ROLLNIP_E_MPA MPa ($theories; symbols: knots)'
set xlabel 'reference angle θ (deg)'
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
  if [ -n "${dense[i]:-}" ]; then
    # f as the program represents it (see dense_pressure), zero beyond theta0.
    fq="$(gq "${dense[i]}.ext")"
  else
    # No knots (a prescribed pressure): f at the surface nodes.
    fq="$(gq "$tmp/nodal_f_$i.csv")"
    awk -F, 'NR == 1 { print "theta_deg,x2_mm,f_MPa"; next } { print $1 "," $5 "," $8 }' "$f" >"$tmp/nodal_f_$i.csv"
  fi
  curves+=("$fq skip 1 using 2:3 with lines lw 2 lc rgb '$c' title 'imposed f, ${labels[$i]}'"
    "$fq skip 1 using (-column(2)):3 with lines lw 2 lc rgb '$c' notitle"
    "$(gq "$f") skip 1 using 5:9 with points pt 6 ps 0.9 lc rgb '$c' title 'normal traction from σ, ${labels[$i]}'"
    "$(gq "$f") skip 1 using (-column(5)):9 with points pt 6 ps 0.9 lc rgb '$c' notitle")
done
if [ "${#curves[@]}" -gt 0 ]; then
  if awk -v b="$bmax" 'BEGIN { exit !(b > 0) }'; then
    xr="$(awk -v b="$bmax" 'BEGIN { printf "[%g:%g]", -1.6 * b, 1.6 * b }')"
  else
    xr="[*:*]"
  fi
  yr="$(awk -v p="$pmax" 'BEGIN { if (p > 0) printf "[%g:%g]", -0.05 * p, 1.12 * p; else print "[*:*]" }')"
  render nip_pressure 900 620 <<EOF
set title 'Pressure across the nip, nonlinear theory (lines: imposed f; circles: -n·σn from the stress)'
set xlabel 'nip coordinate x_2 on the deformed surface (mm)'
set ylabel 'pressure (MPa)'
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
theories="nonlinear theory"
for i in "${!nips[@]}"; do
  d="${nips[$i]}"
  f="$d/bond_surface.csv"
  [ -f "$f" ] || continue
  c="$(colour "$i")"
  rr+=("$(gq "$f") skip 1 using 1:2 with lines lw 2 lc rgb '$c' title 'nonlinear, ${labels[$i]}'")
  rt+=("$(gq "$f") skip 1 using 1:3 with lines lw 2 lc rgb '$c' title 'nonlinear, ${labels[$i]}'")
  m2="$(column_absmax "$f" 2)"
  m3="$(column_absmax "$f" 3)"
  decay+=("$(gq "$f") skip 1 using 1:(abs(column(2))/$m2) with lines lw 2 lc rgb '$c' title '|σ_{rr}|, ${labels[$i]}'")
  decay+=("$(gq "$f") skip 1 using 1:(abs(column(3))/$m3) with $dashed lw 1.5 dt 2 lc rgb '$c' title '|σ_{rθ}|, ${labels[$i]}'")
  fl="$d/linear/bond_surface.csv"
  if [ -f "$fl" ]; then
    theories="solid: nonlinear, $lin_word: linear theory"
    rr+=("$(gq "$fl") skip 1 using 1:2 with $dashed lw 2 dt 2 lc rgb '$c' title 'linear, ${labels[$i]}'")
    rt+=("$(gq "$fl") skip 1 using 1:3 with $dashed lw 2 dt 2 lc rgb '$c' title 'linear, ${labels[$i]}'")
  fi
done
if [ "${#rr[@]}" -gt 0 ]; then
  render bond_stresses 900 900 <<EOF
set multiplot layout 2,1 title 'Cauchy stresses on the bond surface r = R_1 ($theories)'
set grid
set xrange [0:*]
set xlabel 'reference angle θ (deg)'
set key bottom right box opaque font ',9'
set ylabel 'radial stress σ_{rr} (MPa)'
plot $(join ", " "${rr[@]}")
set key top right box opaque font ',9'
set ylabel 'shear stress σ_{rθ} (MPa)'
plot $(join ", " "${rt[@]}")
unset multiplot
EOF
  render bond_stress_decay 900 620 <<EOF
set title 'Decay of the bond stresses away from the nip, nonlinear theory'
set xlabel 'reference angle θ (deg)'
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
  read -r xr yr <<<"$(awk -v b="$b" -v xc="$xc" 'BEGIN {
      w = 2.2 * b; v = 0.36 * w
      printf "[%g:%g] [%g:%g]\n", -w, w, xc - v, xc + v }')"
  u0="$(entry "$d/contact.txt" indentation_u0_mm || true)"
  title="Outer surface near the nip, ${labels[$i]}"
  [ -n "$u0" ] && title="$title, u_0 = $(printf '%.3f' "$u0") mm"
  curves=(
    "$(gq "$f") skip 1 using 3:2 with lines lw 1.5 dt 2 lc rgb '#777777' title 'undeformed surface'"
    "$(gq "$f") skip 1 using (-column(3)):2 with lines lw 1.5 dt 2 lc rgb '#777777' notitle"
    "$(gq "$f") skip 1 using 5:4 with linespoints lw 2 pt 7 ps 0.4 lc rgb '#1f77b4' title 'deformed surface (nodes)'"
    "$(gq "$f") skip 1 using (-column(5)):4 with linespoints lw 2 pt 7 ps 0.4 lc rgb '#1f77b4' notitle"
  )
  if [ -f "$d/indenter.csv" ]; then
    curves+=(
      "$(gq "$d/indenter.csv") skip 1 using 2:1 with lines lw 2 lc rgb '#d62728' title 'indenter'"
      "$(gq "$d/indenter.csv") skip 1 using (-column(2)):1 with lines lw 2 lc rgb '#d62728' notitle"
    )
  fi
  render "$name" 1000 520 <<EOF
set title '$title'
set xlabel 'x_2, along the nip (mm)'
set ylabel 'x_1, along the line of centres (mm)'
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
    # A column is drawn if present with some positive value (P_linear is 0
    # when the linear comparison was off).
    positive() {
      [ -n "$1" ] && awk -F, -v c="$1" 'NR > 1 && $c + 0 > 0 { found = 1 } END { exit !found }' "$characteristic"
    }
    # Each curve is (P, 2b): the load that its theory needs for the width 2b.
    curves=("$fq skip 1 using $cp:(2*column($cb)) with $style lw 2 pt 7 ps 1.2 lc rgb '#1f77b4' title 'nonlinear (this program)'")
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
        curves+=("$(gq "$linb") skip 1 using 2:(2*column(1)) with $style lw 2 dt 2 pt 5 ps 1.1 lc rgb '#d62728' title 'linear theory (this program, same θ_0, its own b)'")
      else
        curves+=("$fq skip 1 using $cl:(2*column($cb)) with $style lw 2 dt 2 pt 5 ps 1.1 lc rgb '#d62728' title 'linear theory (this program, same θ_0, at the nonlinear b)'")
      fi
    fi
    positive "$ch" && curves+=("$fq skip 1 using $ch:(2*column($cb)) with $style lw 1.5 dt 4 pt 9 ps 1.2 lc rgb '#2ca02c' title 'Hertz, incompressible half-space'")
    # The thin-layer asymptote holds for b >> h only (several times too low
    # at b/h = 4, still 25 % at 32): drawn where b/h >= 4, else left out.
    if [ -n "$ct" ] && [ -n "$cbh" ] &&
      awk -F, -v c="$cbh" 'NR > 1 && $c + 0 >= 4 { found = 1 } END { exit !found }' "$characteristic"; then
      curves+=("$fq skip 1 using (column($cbh) >= 4 ? column($ct) : 1/0):(2*column($cb)) with $style lw 1.5 dt 5 pt 11 ps 1.2 lc rgb '#9467bd' title 'thin bonded layer asymptote (b/h ≥ 4)'")
    else
      note "nip_characteristic: no nip has b/h >= 4, the thin-layer asymptote is not drawn"
    fi
    render nip_characteristic 900 620 <<EOF
set title 'Nip characteristic: nip width against line load'
set xlabel 'line load P per unit roll length, two-sided (N/mm = kN/m)'
set ylabel 'full nip width 2b, deformed (mm)'
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
report="$outdir/nip_report.csv"
if [ -f "$report" ] && [ "$(grep -c . "$report")" -ge 2 ]; then
  # The load column names its unit: line_load_kN_per_m, ..._N_per_mm, ..._pli,
  # or a total force on the face length, total_force_N or total_force_kN.
  load_name="$(head -n 1 "$report" | cut -d, -f2)"
  if [[ "$load_name" == total_force_* ]]; then
    load_label="total force (${load_name#total_force_})"
  else
    load_label="line load ($(printf '%s' "${load_name#line_load_}" | sed 's/_per_/\//'))"
  fi
  cw="$(column_of "$report" nip_width_2b_mm)"
  cpk="$(column_of "$report" peak_pressure_MPa)"
  cmn="$(column_of "$report" mean_pressure_MPa)"
  style="linespoints"
  [ "$(grep -c . "$report")" -gt 2 ] || style="points"
  fq="$(gq "$report")"
  render nip_report 900 620 <<EOF
set title 'Nip report: nip width and pressure against line load'
set xlabel '$load_label'
set ylabel 'nip width 2b, deformed (mm)'
set y2label 'pressure (MPa)'
set xrange [0:*]
set yrange [0:*]
set y2range [0:*]
set ytics nomirror
set y2tics
set grid
set key top left box opaque
plot $fq skip 1 using 2:$cw with $style lw 2 pt 7 lc rgb '#1f77b4' title 'nip width 2b (left axis)', \\
     $fq skip 1 using 2:$cpk axes x1y2 with $style lw 2 dt 2 pt 5 lc rgb '#d62728' title 'peak pressure (right axis)', \\
     $fq skip 1 using 2:$cmn axes x1y2 with $style lw 1.5 dt 4 pt 9 lc rgb '#2ca02c' title 'mean pressure P/2b (right axis)'
EOF
else
  note "skipping nip_report: no nip_report.csv, or no rows in it"
fi

[ "${#written[@]}" -gt 0 ] || die "nothing to plot in '$outdir'"
note "wrote ${#written[@]} figure(s) to $plotdir: $(join ", " "${written[@]}")"
