#!/bin/bash
# The effect of the cover's Poisson ratio on the nip of run 30
# (parameters/load_controlled.prm: R1 = 47.2, R0 = 60.7, Rbar = 76.2 mm,
# C1 = C2 = 0.25 MPa, G = 1 MPa) at the same line load P = 10 N/mm and at
# the same approach u0 = 1 mm, default mesh (8 x 18 cells, level 2),
# Q1-P0. Prints one Markdown table per control: nu, K [MPa], P [N/mm],
# u0 [mm], the contact half-width b (half chord of the contact zone) [mm]
# and the peak pressure [MPa], and the changes of b and of the peak
# pressure against the first nu (0.5: incompressible).
#
# Usage: [NUS="0.5 0.49 0.45 0.4 0.3"] bash benchmarks/poisson_ratio.sh
# Uses build/rollnip or $ROLLNIP_BIN; a few minutes on one core.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
rollnip=${ROLLNIP_BIN:-$root/build/rollnip}
nus=${NUS:-0.5 0.49 0.45 0.4 0.3}
[ -x "$rollnip" ] || { echo "poisson_ratio.sh: no $rollnip" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# column CSV NAME: the first data row's value in the column NAME.
column() {
  awk -F, -v k="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == k) c = i }
                     NR == 2 { print $c }' "$1"
}

# run NAME MODE VALUE NU: one nip; prints nu K P u0 b peak
run() {
  cp "$root/parameters/load_controlled.prm" "$tmp/$1.prm"
  cat >>"$tmp/$1.prm" <<EOF
subsection Material
  set Poisson ratio = $4
end
subsection Contact
  set Mode   = $2
  set Values = $3
  set Compare with linear theory = false
end
subsection Output
  set Directory = $tmp/$1
  set Write VTU = false
end
EOF
  "$rollnip" "$tmp/$1.prm" >/dev/null
  local K
  K=$(awk -v nu="$4" 'BEGIN { if (nu >= 0.5) print "inf";
        else printf "%.4g", 2 * (1 + nu) / (3 * (1 - 2 * nu)) }')
  echo "$4 $K $(column "$tmp/$1/nip_characteristic.csv" P_N_per_mm)" \
       "$(column "$tmp/$1/nip_characteristic.csv" u0_mm)" \
       "$(column "$tmp/$1/nip_characteristic.csv" half_chord_mm)" \
       "$(column "$tmp/$1/nip_characteristic.csv" peak_pressure_MPa)"
}

table() {
  echo
  echo "$1"
  echo
  echo "| nu | K [MPa] | P [N/mm] | u0 [mm] | b [mm] | peak p [MPa] | b change | peak change |"
  echo "|---|---|---|---|---|---|---|---|"
  local b0="" p0="" n K P u0 b peak
  for nu in $nus; do
    read -r n K P u0 b peak < <(run "$2-$nu" "$2" "$3" "$nu")
    [ -n "$b0" ] || { b0=$b; p0=$peak; }
    awk -v n="$n" -v K="$K" -v P="$P" -v u0="$u0" -v b="$b" -v p="$peak" \
        -v b0="$b0" -v p0="$p0" 'BEGIN {
      printf "| %s | %s | %.4g | %.4g | %.4g | %.4g | %+.1f %% | %+.1f %% |\n",
             n, K, P, u0, b, p, 100 * (b / b0 - 1), 100 * (p / p0 - 1) }'
  done
}

table "Same line load, P = 10 N/mm:" load 10
table "Same approach, u0 = 1 mm:" indentation 1
