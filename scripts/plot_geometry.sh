#!/usr/bin/env bash
# Draws a labelled sketch of the scene of parameters/batra1980.prm: the rigid
# core (r < R1), the rubber cover (R1 < r < R0), the rigid indenter (radius
# Rbar, centre at (R0 + Rbar - u0, 0), pressed in by u0), the line of centres
# (the X1 axis), the modelled quarter sector 0 <= theta <= 90 deg (shaded),
# the half nip angle theta0 and the four boundary ids of the mesh. Equal
# axis scales, lengths in mm.
#
# Usage: bash scripts/plot_geometry.sh OUTPUT [R1 R0 Rbar u0 theta0]
#   e.g. bash scripts/plot_geometry.sh doc/figures/geometry.png
#   OUTPUT  the figure to write; its ending picks the format: .png (pngcairo)
#           or .svg
#   R1 R0 Rbar u0  in mm, theta0 in deg; defaults 47.2 60.7 76.2 1.37 8
#           (Batra 1980, Spengos run 30; u0 = 1.37 mm is the indentation
#           rollnip finds for the 8 deg nip, 1.3723 mm)
set -euo pipefail

me="plot_geometry"
die() {
  echo "$me: error: $*" >&2
  exit 1
}

if [ "$#" -lt 1 ] || [ "$#" -gt 6 ]; then
  die "usage: bash scripts/plot_geometry.sh OUTPUT [R1 R0 Rbar u0 theta0]"
fi
out="$1"
R1="${2:-47.2}" R0="${3:-60.7}" Rbar="${4:-76.2}" u0="${5:-1.37}" theta0="${6:-8}"
for v in "R1=$R1" "R0=$R0" "Rbar=$Rbar" "u0=$u0" "theta0=$theta0"; do
  awk -v x="${v#*=}" 'BEGIN { exit !(x ~ /^[0-9.]+([eE][-+]?[0-9]+)?$/ && x + 0 > 0) }' ||
    die "${v%%=*} must be a positive number, not '${v#*=}'"
done
awk -v a="$R1" -v b="$R0" -v u="$u0" -v t="$theta0" \
  'BEGIN { exit !(a < b && u < b - a && t < 90) }' ||
  die "need R1 < R0, u0 < R0 - R1 and theta0 < 90 deg"
command -v gnuplot >/dev/null 2>&1 ||
  die "gnuplot not found; install the Debian package gnuplot-nox (bash scripts/setup.sh does)"

case "$out" in
  *.png) terminal="pngcairo enhanced font 'Sans,11' size 1400,860" ;;
  *.svg) terminal="svg enhanced font 'Sans,11' size 1400,860 background '#ffffff'" ;;
  *) die "OUTPUT must end in .png or .svg, not '$out'" ;;
esac
mkdir -p "$(dirname "$out")"
scene="Scene of parameters/batra1980.prm"
[ "$#" -le 1 ] || scene="Roll nip scene"

# render: the gnuplot commands on stdin, drawn into $out.
render() {
  gnuplot -e "set encoding utf8; set terminal $terminal; set output '${out//\'/\'\'}'" - ||
    die "gnuplot failed on $out"
}

render <<EOF
R1 = $R1; R0 = $R0; Rb = $Rbar; u0 = $u0; t0 = $theta0
xc = R0 + Rb - u0                  # centre of the indenter
d = pi / 180
ym = (Rb > R0 ? Rb : R0) + 0.2 * R0
set xrange [-1.45 * R0 : xc + Rb + 0.12 * R0]
set yrange [-ym - 0.35 * R0 : ym]
set size ratio -1
set xlabel 'X_1 (mm)'
set ylabel 'X_2 (mm)'
set tics out nomirror
set title '$scene: plane strain, lengths in mm; the modelled quarter sector is shaded' font ',12'

# Bodies, back to front.
set object 1 circle at 0,0 size R0 back fc rgb '#fbe6d2' fs solid 1 border lc rgb '#b07040' dt 2
set object 2 circle at 0,0 size R0 arc [0:90] back fc rgb '#ee9a55' fs solid 1 border lc rgb '#b07040'
set object 3 circle at 0,0 size R1 back fc rgb '#b9b9b9' fs solid 1 border lc rgb '#555555'
set object 4 circle at xc,0 size Rb back fc rgb '#4a7fd0' fs transparent solid 0.18 border lc rgb '#1f4e9a' lw 2
# The boundary ids: thick lines on the edges of the quarter sector.
set object 5 circle at 0,0 size R1 arc [0:90] nowedge front fs empty border lc rgb '#000000' lw 4
set object 6 circle at 0,0 size R0 arc [0:90] nowedge front fs empty border lc rgb '#000000' lw 4
set object 7 circle at 0,0 size R0 arc [0:t0] nowedge front fs empty border lc rgb '#d62728' lw 6
set arrow 1 from R1,0 to R0,0 nohead front lc rgb '#000000' lw 4
set arrow 2 from 0,R1 to 0,R0 nohead front lc rgb '#000000' lw 4
# Line of centres (X1) and the X2 axis.
set arrow 3 from -1.4 * R0,0 to xc + Rb + 0.1 * R0,0 front lc rgb '#333333' lw 1 dt '-.' size 4,20
set arrow 4 from 0,0 to 0,ym - 0.05 * R0 front lc rgb '#333333' lw 1 dt '-.' size 4,20
set label 1 'X_1' at xc + Rb + 0.1 * R0, 0.06 * R0 right front font ',13'
set label 2 'X_2' at 0.04 * R0, ym - 0.07 * R0 left front font ',13'
set label 3 'line of centres' at xc + 0.1 * Rb, -0.06 * R0 left front tc rgb '#333333'
set object 8 circle at 0,0 size 0.012 * R0 front fc rgb '#000000' fs solid
set object 9 circle at xc,0 size 0.012 * R0 front fc rgb '#1f4e9a' fs solid
set label 4 'roll axis' at 0.04 * R0, -0.08 * R0 left front
set label 5 sprintf('indenter centre (R_0 + R̄ - u_0, 0) = (%.2f, 0)', xc) at xc, -0.2 * R0 centre front tc rgb '#1f4e9a'

# Radii.
set arrow 10 from 0,0 to R1 * cos(135 * d), R1 * sin(135 * d) front lc rgb '#000000' lw 1.5
set label 10 sprintf('R_1 = %g', R1) at 0.55 * R1 * cos(135 * d), 0.55 * R1 * sin(135 * d) right offset -0.8,0 front
set arrow 11 from 0,0 to R0 * cos(200 * d), R0 * sin(200 * d) front lc rgb '#000000' lw 1.5
set label 11 sprintf('R_0 = %g', R0) at 0.6 * R0 * cos(200 * d), 0.6 * R0 * sin(200 * d) centre offset 0,1 front
set arrow 12 from xc,0 to xc + Rb * cos(60 * d), Rb * sin(60 * d) front lc rgb '#1f4e9a' lw 1.5
set label 12 sprintf('R̄ = %g', Rb) at xc + 0.5 * Rb * cos(60 * d), 0.5 * Rb * sin(60 * d) left offset 1,0 front tc rgb '#1f4e9a'

# theta0: its ray, an arc and the nip on the outer arc.
set arrow 13 from 0,0 to 1.02 * R0 * cos(t0 * d), 1.02 * R0 * sin(t0 * d) nohead front lc rgb '#d62728' lw 1.5 dt 2
set object 14 circle at 0,0 size 0.5 * R1 arc [0:t0] nowedge front fs empty border lc rgb '#d62728' lw 2
set label 14 sprintf('θ_0 = %g°', t0) at 0.5 * R1, 0.5 * R1 * sin(t0 * d) + 0.14 * R0 centre front tc rgb '#d62728'
set arrow 15 from 0.5 * R1, 0.5 * R1 * sin(t0 * d) + 0.1 * R0 to 0.5 * R1 * cos(t0 * d / 2), 0.5 * R1 * sin(t0 * d / 2) front lc rgb '#d62728' lw 1 size 1.5,20
set label 16 sprintf('u_0 = %g: indentation (overlap of the undeformed circles)', u0) at R0 + 0.1 * R0, -0.5 * R0 left front
set arrow 16 from R0 + 0.09 * R0, -0.48 * R0 to R0 - u0 / 2, -0.01 * R0 front lc rgb '#000000' lw 1 size 1.5,20

# Boundary ids: a tag at each edge, explained in a block below the roll.
set label 20 'id 0' at 0.82 * R1 * cos(50 * d), 0.82 * R1 * sin(50 * d) centre front font ',12'
set label 21 'id 1' at 1.1 * R0 * cos(65 * d), 1.1 * R0 * sin(65 * d) centre front font ',12'
set label 22 'id 2' at 0.5 * (R1 + R0), -0.1 * R0 centre front font ',12'
set label 23 'id 3' at -0.04 * R0, 0.5 * (R1 + R0) right front font ',12'
dy = 0.034 * (2 * ym + 0.35 * R0); y0 = -ym - 0.35 * R0 + 4.6 * dy; x0 = -1.38 * R0
set label 24 'Boundary ids of the mesh (edges of the quarter, thick):' at x0, y0 left front
set label 25 'id 0  inner arc r = R_1: bonded to the rigid core (fixed)' at x0, y0 - dy left front
set label 26 'id 1  outer arc r = R_0: contact, follower pressure f(θ) for θ < θ_0 (red)' at x0, y0 - 2 * dy left front
set label 27 'id 2  symmetry edge X_2 = 0, on the line of centres' at x0, y0 - 3 * dy left front
set label 28 'id 3  far edge θ = 90°: free' at x0, y0 - 4 * dy left front

# Bodies named.
set label 30 'rigid core' at 0, -0.6 * R1 centre front
set label 31 'rubber cover: modelled quarter 0 ≤ θ ≤ 90°' at 0.9 * R0, 0.9 * R0 left front
set arrow 31 from 0.88 * R0, 0.89 * R0 to 0.5 * (R1 + R0) * cos(40 * d), 0.5 * (R1 + R0) * sin(40 * d) front lw 1 size 1.5,20
set label 32 'not modelled (symmetry)' at 0, -0.5 * (R1 + R0) centre front tc rgb '#8a5a30'
set label 33 'rigid indenter' at xc, -0.6 * Rb centre front tc rgb '#1f4e9a' font ',12'

plot NaN notitle
EOF
echo "$me: wrote $out"
