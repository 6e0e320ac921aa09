#!/usr/bin/env bash
# A 3D scene (parameters/slice_3d.prm, or free_end_3d.prm with its free
# end's measures in summary.txt) gives the same P(u0) and contact sizes on
# one and on two MPI processes, and its parallel output is one .pvtu record
# with a piece per process.
#
# Usage: bash mpi_equivalence_3d.sh ROLLNIP MPIEXEC NUMDIFF PRM
#
# Runs PRM at mesh level 0 with two cells through the thickness (so that
# the partition cuts the slice), once without mpirun and once with
# 'MPIEXEC -np 2', and compares slice_3d.csv and summary.txt (without the
# timings and the process count) with numdiff, relative 1e-8 (Newton stops
# at a relative residual of 1e-10).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 4 ] || fail "usage: mpi_equivalence_3d.sh ROLLNIP MPIEXEC NUMDIFF PRM"
rollnip="$(realpath "$1")"
mpiexec="$2"
numdiff="$3"
scene="$(realpath "$4")"
require_executable rollnip "$rollnip"
require_executable "mpiexec (MPIEXEC_EXECUTABLE)" "$mpiexec"
require_executable "numdiff (needed to compare the results)" "$numdiff"
start_test "mpi_equivalence_3d"

if [ "$(id -u)" -eq 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
mpi_flags=()
mpi_version="$("$mpiexec" --version 2>&1 || true)"
if [[ "$mpi_version" == *"Open MPI"* || "$mpi_version" == *OpenRTE* ||
      "$mpi_version" == *open-mpi* ]]; then
  mpi_flags+=(--oversubscribe)
fi

make_prm()
{
  cp "$scene" "$1"
  printf '\nsubsection Mesh\n  set Global refinements = 0\nend\n' >> "$1"
  printf 'subsection Three d\n  set Layers = 2\nend\n' >> "$1"
  printf 'subsection Output\n  set Directory = %s\nend\n' "$2" >> "$1"
}
make_prm serial.prm out_serial
make_prm parallel.prm out_parallel

"$rollnip" serial.prm > serial.log 2>&1 || { cat serial.log; fail "the serial run failed"; }
pass "serial run finished"
rc=0
timeout --kill-after=10 300 "$mpiexec" "${mpi_flags[@]}" -np 2 "$rollnip" \
  parallel.prm > parallel.log 2>&1 || rc=$?
[ "$rc" -eq 0 ] || { cat parallel.log; fail "the run on 2 MPI processes failed (exit code $rc)"; }
pass "run on 2 MPI processes finished"

[ "$(summary_value out_serial/summary.txt mpi_processes)" -eq 1 ] &&
  [ "$(summary_value out_parallel/summary.txt mpi_processes)" -eq 2 ] ||
  fail "summary.txt does not report mpi_processes = 1 and 2"
pass "summary.txt reports mpi_processes = 1 and 2"
n="$(grep -c '<Piece ' out_parallel/slice_3d_00.pvtu)"
[ "$n" -eq 2 ] || fail "out_parallel/slice_3d_00.pvtu has $n pieces, expected 2"
[ -f out_parallel/slice_3d_00.0.vtu ] && [ -f out_parallel/slice_3d_00.1.vtu ] ||
  fail "the two .vtu pieces of slice_3d_00.pvtu are missing"
pass "slice_3d_00.pvtu names one piece per process, both written"

for dir in out_serial out_parallel; do
  grep -v -E '^(wall_time_s|mpi_processes) =' "$dir/summary.txt" > "$dir/summary_compared.txt"
  cut -d, -f1-7 "$dir/slice_3d.csv" > "$dir/slice_compared.csv"
done
for f in summary_compared.txt slice_compared.csv; do
  if "$numdiff" --quiet -r 1e-8 -a 1e-12 -s $' \t\n,=' "out_serial/$f" "out_parallel/$f" > /dev/null; then
    pass "$f: serial and 2 processes agree (rel 1e-8)"
  else
    "$numdiff" -r 1e-8 -a 1e-12 -s $' \t\n,=' "out_serial/$f" "out_parallel/$f" | tail -n 20 || true
    fail "$f differs between 1 and 2 MPI processes"
  fi
done
# The outputs a 3D scene adds: the contact patch, and the line load beside
# the core's deflection.
for f in contact_patch.txt core_deflection_along_axis.csv; do
  [ -f "out_serial/$f" ] || continue
  if "$numdiff" --quiet -r 1e-8 -a 1e-12 -s $' \t\n,=' "out_serial/$f" "out_parallel/$f" > /dev/null; then
    pass "$f: serial and 2 processes agree (rel 1e-8)"
  else
    "$numdiff" -r 1e-8 -a 1e-12 -s $' \t\n,=' "out_serial/$f" "out_parallel/$f" | tail -n 20 || true
    fail "$f differs between 1 and 2 MPI processes"
  fi
done
echo "serial:   P = $(summary_value out_serial/summary.txt nip_load_P_N_per_mm) N/mm"
echo "parallel: P = $(summary_value out_parallel/summary.txt nip_load_P_N_per_mm) N/mm"
