#!/usr/bin/env bash
# The 3D body gives the same answer with Linear solver/Method = gmres-amg
# (GMRES with the augmented-Lagrangian block AMG preconditioner) as with
# the direct solver: the same Newton steps and active sets, P(u0), the
# half-chords and the line load along the axis to 1e-6 relative (GMRES
# stops at 1e-9 of the right-hand side, Newton at a relative residual of
# 1e-10), on NP processes (default 1), and each run prints its solver.
#
# Usage: bash solver_equivalence_3d.sh ROLLNIP MPIEXEC NUMDIFF PRM [NP [ELEMENT]]
#
# Runs PRM at mesh level LEVEL (default 1) with LAYERS cells through the
# thickness (default 2), once per method; ELEMENT
# (Q1-P0 or Q2-P1), if given, is Discretization/Element of both. With an
# elastic core the core's deflection and bending stress along the axis
# are compared too.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -ge 4 ] && [ $# -le 6 ] ||
  fail "usage: solver_equivalence_3d.sh ROLLNIP MPIEXEC NUMDIFF PRM [NP [ELEMENT]]"
rollnip="$(realpath "$1")"
mpiexec="$2"
numdiff="$3"
scene="$(realpath "$4")"
np="${5:-1}"
element="${6:-}"
level="${LEVEL:-1}"
layers="${LAYERS:-2}"
[[ "$np" =~ ^[1-9][0-9]*$ ]] || fail "NP must be a positive integer, got '$np'"
require_executable rollnip "$rollnip"
require_executable "numdiff (needed to compare the results)" "$numdiff"
start_test "solver_equivalence_3d"

launcher=()
if [ "$np" -gt 1 ]; then
  require_executable "mpiexec (MPIEXEC_EXECUTABLE)" "$mpiexec"
  if [ "$(id -u)" -eq 0 ]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  fi
  launcher=("$mpiexec" -np "$np")
  mpi_version="$("$mpiexec" --version 2>&1 || true)"
  [[ "$mpi_version" == *"Open MPI"* || "$mpi_version" == *OpenRTE* ]] &&
    launcher+=(--oversubscribe)
fi

for method in direct gmres-amg; do
  cp "$scene" "$method.prm"
  printf '\nsubsection Mesh\n  set Global refinements = %s\nend\n' "$level" >> "$method.prm"
  printf 'subsection Three d\n  set Layers = %s\nend\n' "$layers" >> "$method.prm"
  printf 'subsection Linear solver\n  set Method = %s\nend\n' "$method" >> "$method.prm"
  if [ -n "$element" ]; then
    printf 'subsection Discretization\n  set Element = %s\nend\n' "$element" >> "$method.prm"
  fi
  printf 'subsection Output\n  set Directory = out_%s\n  set Write VTU = false\nend\n' \
    "$method" >> "$method.prm"
  rc=0
  timeout --kill-after=10 600 "${launcher[@]}" "$rollnip" "$method.prm" > "$method.log" 2>&1 || rc=$?
  [ "$rc" -eq 0 ] || { cat "$method.log"; fail "the $method run failed (exit code $rc)"; }
  grep -q "linear solver: $method" "$method.log" ||
    fail "$method.log does not print 'linear solver: $method'"
  pass "$method run (${element:-element of PRM}) on $np process(es) finished and printed its solver"
done

# The iterative run did iterate; the direct one did not.
gmres="$(awk -F, 'NR > 1 { n += $9 } END { print n + 0 }' out_gmres-amg/slice_3d.csv)"
direct="$(awk -F, 'NR > 1 { n += $9 } END { print n + 0 }' out_direct/slice_3d.csv)"
[ "$gmres" -gt 0 ] && [ "$direct" -eq 0 ] ||
  fail "GMRES iterations: $gmres with gmres-amg, $direct with direct"
pass "gmres-amg took $gmres GMRES iterations, direct none"

# The direct solver analyses the fixed pattern once and refactorises
# at every Newton step; gmres-amg factorises nothing.
newton="$(awk -F, 'NR > 1 { n += $6 } END { print n + 0 }' out_direct/slice_3d.csv)"
check_close "symbolic analyses, direct" "$(summary_value out_direct/summary.txt symbolic_factorisations)" 1 0
check_close "factorisations, direct (= Newton steps)" "$(summary_value out_direct/summary.txt factorisations)" "$newton" 0
check_close "factorisations, gmres-amg" "$(summary_value out_gmres-amg/summary.txt factorisations)" 0 0

for dir in out_direct out_gmres-amg; do
  grep -v -E '^(wall_time_s|mpi_processes|linear_solver|symbolic_factorisations|factorisations) =' "$dir/summary.txt" > "$dir/summary_compared.txt"
  cut -d, -f1-7 "$dir/slice_3d.csv" > "$dir/slice_compared.csv"
done
compared=(summary_compared.txt slice_compared.csv line_load_along_axis.csv)
for f in core_deflection_along_axis.csv core_bending_stress_along_axis.csv; do
  if [ -f "out_direct/$f" ]; then compared+=("$f"); fi
done
for f in "${compared[@]}"; do
  files_agree "$numdiff" 1e-6 1e-9 "out_direct/$f" "out_gmres-amg/$f" ||
    fail "$f differs between gmres-amg and direct"
  pass "$f: gmres-amg and direct agree (rel 1e-6)"
done
echo "direct:    P = $(summary_value out_direct/summary.txt nip_load_P_N_per_mm) N/mm"
echo "gmres-amg: P = $(summary_value out_gmres-amg/summary.txt nip_load_P_N_per_mm) N/mm"
