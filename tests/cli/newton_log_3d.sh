#!/usr/bin/env bash
# The Newton log of a 3D run (Output/Verbosity = detailed): PRM at mesh
# level 0 with two cells through the thickness, the approaches 0.5 and 1 mm
# with Three d/Approach step = 0.5, Linear solver/Method = gmres-amg, on NP
# MPI processes (default 2). Checks that rank 0 alone prints the log: one
# table per approach, one line per Newton step (as many as slice_3d.csv
# counts), their GMRES iterations summing to the CSV's, the indenter's move
# of 0.5 mm as the first step's gap, and a "converged" line per approach
# within Newton's tolerances; and that Verbosity = normal prints none of it.
#
# Usage: bash newton_log_3d.sh ROLLNIP MPIEXEC PRM [NP]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -ge 3 ] && [ $# -le 4 ] ||
  fail "usage: newton_log_3d.sh ROLLNIP MPIEXEC PRM [NP]"
rollnip="$(realpath "$1")"
mpiexec="$2"
scene="$(realpath "$3")"
np="${4:-2}"
require_executable rollnip "$rollnip"
require_executable "mpiexec (MPIEXEC_EXECUTABLE)" "$mpiexec"
start_test "newton_log_3d"
mpi_setup "$mpiexec"

run()
{
  cp "$scene" "$1.prm"
  cat >> "$1.prm" <<PRM

subsection Mesh
  set Global refinements = 0
end
subsection Three d
  set Layers        = 2
  set Approach step = 0.5
end
subsection Contact
  set Values = 0.5, 1
end
subsection Linear solver
  set Method = gmres-amg
end
subsection Output
  set Directory = out_$1
  set Write VTU = false
  set Verbosity = $2
end
PRM
  local rc=0
  timeout --kill-after=10 300 "$mpiexec" "${mpi_flags[@]}" -np "$np" \
    "$rollnip" "$1.prm" > "$1.log" 2>&1 || rc=$?
  [ "$rc" -eq 0 ] || { cat "$1.log"; fail "the $2 run on $np processes failed (exit code $rc)"; }
}

run detailed detailed
log=detailed.log
csv=out_detailed/slice_3d.csv
read -r newton gmres < <(awk -F, 'NR > 1 { n += $6; g += $9 } END { print n + 0, g + 0 }' "$csv")
[ "$newton" -gt 0 ] || fail "no Newton step in $csv"

tables="$(grep -c '^    Newton at u0 = ' "$log" || true)"
[ "$tables" -eq 2 ] || fail "$tables Newton tables in $log, expected one per approach (2): rank 0 alone prints"
pass "one Newton table per approach (2)"

# A step line: step number, |R_u|/|F|, sum|J-1|/V, the largest gap of an
# active node [mm], active nodes, GMRES iterations, seconds.
step_line='$1 ~ /^[0-9]+$/ && NF == 7 && $2 ~ /e/'
read -r lines its < <(awk "$step_line"' { n++; g += $6 } END { print n + 0, g + 0 }' "$log")
[ "$lines" -eq "$newton" ] || fail "$lines Newton step lines, slice_3d.csv counts $newton steps"
pass "$lines Newton step lines = the $newton steps of slice_3d.csv"
[ "$its" -eq "$gmres" ] || fail "the step lines sum $its GMRES iterations, slice_3d.csv $gmres"
pass "their GMRES iterations sum to slice_3d.csv's ($gmres)"

# The first step of the first approach sees the indenter's move: the
# node on the symmetry plane penetrates by u0 = 0.5 mm.
first_gap="$(awk "$step_line"' { print $4; exit }' "$log")"
check_rel_close "gap of the first step [mm]" "$first_gap" 0.5 1e-6

# Each approach ends converged: |R_u|/|F| below 1e-10, every active node
# on the indenter (Newton's test: 1e-10 of the 60.7 mm radius).
converged="$(grep -c 'converged: |R_u|/|F| = ' "$log" || true)"
[ "$converged" -eq 2 ] || fail "$converged converged lines, expected 2"
while read -r residual gap; do
  check_less "final |R_u|/|F|" "$residual" 1e-10
  check_less "final gap [mm]" "$gap" 6.07e-9
done < <(sed -n 's/.*converged: |R_u|\/|F| = \([^,]*\),.*gap = \([^ ]*\) mm.*/\1 \2/p' "$log")

run normal normal
if grep -q -e 'Newton at u0' -e 'converged:' normal.log; then
  fail "Verbosity = normal prints the Newton log"
fi
pass "Verbosity = normal prints no Newton log"
