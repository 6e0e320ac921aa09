#!/usr/bin/env bash
# What the rolling post-process (doc/rolling.md) costs beside the nip it
# follows: parameters/rolling_heat.prm with one nip (20 kN/m), no error
# estimate and no VTU, at mesh levels 1, 2, 3 with Q1-P0 and 0, 1, 2 with
# Q2-P1. One table row per run.
#
# Usage: bash benchmarks/rolling_cost.sh
# Uses build/rollnip of this repository, or $ROLLNIP_BIN.
#
# Columns (wall times in seconds, from the nip's contact.txt):
#   nip s    nip_solve_wall_time_s: the contact solve of the nip (load
#            control, every contact iteration)
#   loss s   rolling_loss_wall_time_s: sampling the circles and the
#            first-order loss at all 5 speeds of the speed table
#   heat s   rolling_temperature_wall_time_s: the cover's temperature,
#            one conduction solve per speed (5)
#   ratio    (loss s + heat s) / nip s
#
# Then the full steady rolling (parameters/rolling_full.prm, its own
# whole-circle mesh, the nip at level 1), one row per speed from
# rolling_full.csv: V tau / b, the fixed-point iterations and the CPU time
# of that speed's solve (speed 0: the elastic whole-circle nip), beside the
# CPU time of the nip it starts from.
set -euo pipefail

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
rollnip="${ROLLNIP_BIN:-$repo_root/build/rollnip}"
[ -x "$rollnip" ] || { echo "rolling_cost: error: no executable '$rollnip'" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

value() { awk -F' = ' -v k="$2" '$1 == k { print $2 }' "$1"; }

printf '%-7s %5s %7s %9s %9s %9s %8s %7s\n' element level cells "nip s" "loss s" "heat s" ratio "F_r"
for case in "Q1-P0 1" "Q1-P0 2" "Q1-P0 3" "Q2-P1 0" "Q2-P1 1" "Q2-P1 2"; do
  read -r element level <<< "$case"
  prm="$work/run.prm"
  cp "$repo_root/parameters/rolling_heat.prm" "$prm"
  cat >> "$prm" <<PRM
subsection Mesh
  set Global refinements = $level
end
subsection Discretization
  set Element = $element
end
subsection Contact
  set Values = 20
end
subsection Accuracy
  set Error estimate = false
end
subsection Output
  set Directory = $work/out
  set Write VTU = false
end
PRM
  rm -rf "$work/out"
  "$rollnip" "$prm" > "$work/log.txt" 2>&1 ||
    { cat "$work/log.txt" >&2; echo "rolling_cost: error: run failed" >&2; exit 1; }
  c="$work/out/contact.txt"
  nip="$(value "$c" nip_solve_wall_time_s)"
  loss="$(value "$c" rolling_loss_wall_time_s)"
  heat="$(value "$c" rolling_temperature_wall_time_s)"
  fr="$(value "$c" rolling_resistance_N_per_mm)"
  cells="$(value "$work/out/summary.txt" cells)"
  awk -v e="$element" -v l="$level" -v n="$cells" -v a="$nip" -v b="$loss" \
      -v h="$heat" -v f="$fr" \
      'BEGIN { printf "%-7s %5d %7d %9.3f %9.4f %9.4f %8.4f %7.4f\n", e, l, n, a, b, h, (b + h) / a, f }'
done

echo
echo "Full steady rolling, parameters/rolling_full.prm (nip at level 1):"
prm="$work/full.prm"
cp "$repo_root/parameters/rolling_full.prm" "$prm"
cat >> "$prm" <<PRM
subsection Mesh
  set Global refinements = 1
end
subsection Output
  set Directory = $work/full
  set Write VTU = false
end
PRM
"$rollnip" "$prm" > "$work/full_log.txt" 2>&1 ||
  { cat "$work/full_log.txt" >&2; echo "rolling_cost: error: full rolling run failed" >&2; exit 1; }
echo "nip solve: $(value "$work/full/contact.txt" nip_solve_wall_time_s) s wall"
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i
                   printf "%10s %10s %10s %8s %10s\n", "V m/min", "V tau/b", "F_r N/mm", "iters", "CPU s" }
         NR > 1 { printf "%10g %10.4g %10.4g %8d %10.2f\n", $c["speed_m_per_min"], $c["V_tau_over_b"],
                  $c["F_r_energy_N_per_mm"], $c["fixed_point_iterations"], $c["cpu_time_s"] }' \
  "$work/full/rolling_full.csv"
