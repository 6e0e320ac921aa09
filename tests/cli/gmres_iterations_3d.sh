#!/usr/bin/env bash
# The GMRES iterations per Newton solve of Linear solver/Method = gmres-amg
# stay bounded as the mesh is refined: PRM (two cells through the
# thickness, one approach u0 = 0.5 mm) at mesh levels FIRST and FIRST + 1
# with Discretization/Element = ELEMENT (default Q2-P1), one process. Checks
# that every level's GMRES iterations per Newton solve (summed over the
# solves of slice_3d.csv over its Newton steps) are at most MAX_PER_SOLVE
# and that the finer level needs at most GROWTH times the coarser level's.
# With the stable Q2-P1 pair the count does not grow; with Q1-P0 it grows
# about 3 times from level 0 to 1 (doc/three_d.md).
#
# Usage: bash gmres_iterations_3d.sh ROLLNIP PRM MAX_PER_SOLVE GROWTH
# Environment: ELEMENT (default Q2-P1), FIRST (default 0).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 4 ] || fail "usage: gmres_iterations_3d.sh ROLLNIP PRM MAX_PER_SOLVE GROWTH"
rollnip="$(realpath "$1")"
scene="$(realpath "$2")"
max_per_solve="$3"
growth="$4"
element="${ELEMENT:-Q2-P1}"
first="${FIRST:-0}"
require_executable rollnip "$rollnip"
start_test "gmres_iterations_3d"

per_solve=()
for level in "$first" "$((first + 1))"; do
  prm="level_$level.prm"
  cp "$scene" "$prm"
  cat >> "$prm" <<PRM

subsection Mesh
  set Global refinements = $level
end
subsection Three d
  set Layers = 2
end
subsection Contact
  set Values = 0.5
end
subsection Discretization
  set Element = $element
end
subsection Linear solver
  set Method = gmres-amg
end
subsection Output
  set Directory = out_$level
  set Write VTU = false
end
PRM
  rc=0
  timeout --kill-after=10 900 "$rollnip" "$prm" > "level_$level.log" 2>&1 || rc=$?
  [ "$rc" -eq 0 ] || { cat "level_$level.log"; fail "the run at level $level failed (exit code $rc)"; }
  read -r newton gmres < <(awk -F, 'NR > 1 { n += $6; g += $9 } END { print n + 0, g + 0 }' "out_$level/slice_3d.csv")
  [ "$newton" -gt 0 ] || fail "level $level: no Newton step in slice_3d.csv"
  ratio="$(awk -v g="$gmres" -v n="$newton" 'BEGIN { printf "%.2f", g / n }')"
  echo "level $level ($element, $(summary_value "out_$level/summary.txt" n_dofs) DoFs): $gmres GMRES iterations over $newton Newton solves, $ratio per solve"
  awk -v r="$ratio" -v m="$max_per_solve" 'BEGIN { exit !(r <= m) }' ||
    fail "level $level: $ratio GMRES iterations per solve, above $max_per_solve"
  pass "level $level: $ratio GMRES iterations per solve <= $max_per_solve"
  per_solve+=("$ratio")
done

awk -v a="${per_solve[0]}" -v b="${per_solve[1]}" -v g="$growth" 'BEGIN { exit !(b <= g * a) }' ||
  fail "per solve: ${per_solve[1]} at level $((first + 1)) against ${per_solve[0]} at level $first, more than $growth times"
pass "per solve: ${per_solve[1]} at level $((first + 1)) <= $growth x ${per_solve[0]} at level $first"
