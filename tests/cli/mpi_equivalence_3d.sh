#!/usr/bin/env bash
# A 3D scene (parameters/slice_3d.prm, or the bent core, short roller,
# free end or elastic core with their own outputs) gives the same P(u0)
# and contact sizes on one and on NP MPI processes, and its parallel
# output is one .pvtu record with a piece per process.
#
# Usage: bash mpi_equivalence_3d.sh ROLLNIP MPIEXEC NUMDIFF PRM [NP [METHOD]]
#
# Runs PRM at mesh level 0 with two cells through the thickness (so that
# the partition cuts the slice), once without mpirun and once with
# 'MPIEXEC -np NP' (default 2; Open MPI gets --oversubscribe, so NP may
# exceed the cores), and compares slice_3d.csv and summary.txt (without
# the timings and the process count) with numdiff, relative 1e-8 (Newton
# stops at a relative residual of 1e-10). METHOD (default direct) is
# Linear solver/Method of both runs: gmres-amg checks the iterative path,
# whose AMG hierarchy depends on the partition. The environment variable
# ELEMENT (Q1-P0 or Q2-P1), if set, is Discretization/Element of both.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -ge 4 ] && [ $# -le 6 ] ||
  fail "usage: mpi_equivalence_3d.sh ROLLNIP MPIEXEC NUMDIFF PRM [NP [METHOD]]"
rollnip="$(realpath "$1")"
mpiexec="$2"
numdiff="$3"
scene="$(realpath "$4")"
np="${5:-2}"
method="${6:-direct}"
[[ "$np" =~ ^[1-9][0-9]*$ ]] && [ "$np" -ge 2 ] ||
  fail "NP must be an integer of at least 2, got '$np'"
require_executable rollnip "$rollnip"
require_executable "mpiexec (MPIEXEC_EXECUTABLE)" "$mpiexec"
require_executable "numdiff (needed to compare the results)" "$numdiff"
start_test "mpi_equivalence_3d"

mpi_setup "$mpiexec"

make_prm()
{
  cp "$scene" "$1"
  printf '\nsubsection Mesh\n  set Global refinements = 0\nend\n' >> "$1"
  printf 'subsection Three d\n  set Layers = 2\nend\n' >> "$1"
  printf 'subsection Output\n  set Directory = %s\nend\n' "$2" >> "$1"
  printf 'subsection Linear solver\n  set Method = %s\nend\n' "$method" >> "$1"
  if [ -n "${ELEMENT:-}" ]; then
    printf 'subsection Discretization\n  set Element = %s\nend\n' "$ELEMENT" >> "$1"
  fi
}
make_prm serial.prm out_serial
make_prm parallel.prm out_parallel

"$rollnip" serial.prm > serial.log 2>&1 || { cat serial.log; fail "the serial run failed"; }
pass "serial run finished"
rc=0
timeout --kill-after=10 300 "$mpiexec" "${mpi_flags[@]}" -np "$np" "$rollnip" \
  parallel.prm > parallel.log 2>&1 || rc=$?
[ "$rc" -eq 0 ] || { cat parallel.log; fail "the run on $np MPI processes failed (exit code $rc)"; }
pass "run on $np MPI processes finished"
for log in serial.log parallel.log; do
  grep -q "linear solver: $method" "$log" ||
    fail "$log does not print 'linear solver: $method'"
done
pass "both runs print 'linear solver: $method'"

[ "$(summary_value out_serial/summary.txt mpi_processes)" -eq 1 ] &&
  [ "$(summary_value out_parallel/summary.txt mpi_processes)" -eq "$np" ] ||
  fail "summary.txt does not report mpi_processes = 1 and $np"
pass "summary.txt reports mpi_processes = 1 and $np"
n="$(grep -c '<Piece ' out_parallel/slice_3d_00.pvtu)"
[ "$n" -eq "$np" ] || fail "out_parallel/slice_3d_00.pvtu has $n pieces, expected $np"
for ((rank = 0; rank < np; ++rank)); do
  [ -f "out_parallel/slice_3d_00.$rank.vtu" ] ||
    fail "the .vtu piece of rank $rank (out_parallel/slice_3d_00.$rank.vtu) is missing"
done
pass "slice_3d_00.pvtu names one piece per process, all $np written"

for dir in out_serial out_parallel; do
  grep -v -E '^(wall_time_s|mpi_processes) =' "$dir/summary.txt" > "$dir/summary_compared.txt"
  cut -d, -f1-7 "$dir/slice_3d.csv" > "$dir/slice_compared.csv"
done
for f in summary_compared.txt slice_compared.csv; do
  files_agree "$numdiff" 1e-8 1e-12 "out_serial/$f" "out_parallel/$f" ||
    fail "$f differs between 1 and $np MPI processes"
  pass "$f: serial and $np processes agree (rel 1e-8)"
done
# The outputs a 3D scene adds: the contact patch, the line load beside
# the core's deflection, and the elastic core's bending stresses.
for f in contact_patch.txt core_deflection_along_axis.csv \
  core_bending_stress_along_axis.csv; do
  [ -f "out_serial/$f" ] || continue
  files_agree "$numdiff" 1e-8 1e-12 "out_serial/$f" "out_parallel/$f" ||
    fail "$f differs between 1 and $np MPI processes"
  pass "$f: serial and $np processes agree (rel 1e-8)"
done
echo "serial:   P = $(summary_value out_serial/summary.txt nip_load_P_N_per_mm) N/mm"
echo "parallel: P = $(summary_value out_parallel/summary.txt nip_load_P_N_per_mm) N/mm"
