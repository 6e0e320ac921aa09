#!/usr/bin/env bash
# One process and two MPI processes must give the same results.
#
# Usage: bash mpi_equivalence.sh ROLLNIP MPIEXEC NUMDIFF PRM [METHOD]
#   PRM     a shipped scene: parameters/parabolic_pressure.prm (the paper's
#           pressure scene) or a contact scene such as
#           parameters/load_controlled.prm (nip-fitted mesh, load control)
#           or parameters/two_rolls.prm (two covered rolls: the mating
#           roll gets the same small mesh and its files are compared too)
#   METHOD  Linear solver/Method: direct (default) or gmres-amg
#
# Runs the scene of PRM on a smaller mesh (the overrides are appended to a
# copy: a later 'set' wins) once without mpirun and once with 'MPIEXEC -np 2',
# each with its own output directory, then compares with numdiff (relative
# tolerance 1e-8, absolute 1e-12, fields split at blanks, commas and '='):
# summary.txt without the lines that must differ (timings, mpi_processes,
# threads, the GMRES counts), outer_surface.csv and bond_surface.csv; for a
# contact scene these of every nip-NN/ directory, its contact_pressure.csv,
# and nip_characteristic.csv. With gmres-amg the AMG hierarchy differs
# between one and two processes; Newton still converges to the same state.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 4 ] || [ $# -eq 5 ] ||
  fail "usage: mpi_equivalence.sh ROLLNIP MPIEXEC NUMDIFF PRM [METHOD]"
rollnip="$1"
mpiexec="$2"
numdiff="$3"
scene="$4"
method="${5:-direct}"
require_executable rollnip "$rollnip"
require_executable "mpiexec (MPIEXEC_EXECUTABLE)" "$mpiexec"
require_executable "numdiff (needed to compare the results)" "$numdiff"
[ -f "$scene" ] || fail "parameter file '$scene' not found"
start_test "mpi_equivalence_$(basename "$scene" .prm)_$method"

mpi_setup "$mpiexec"

make_prm()
{
  cp "$scene" "$1"
  cat >> "$1" <<PRM

# --- overrides of tests/cli/mpi_equivalence.sh: a small mesh, own output
subsection Mesh
  set Radial cells          = 3
  set Circumferential cells = 16
  set Global refinements    = 0
end
subsection Output
  set Directory    = $2
  set Print timing = false
end
subsection Linear solver
  set Method = $method
end
PRM
  # A covered mating roll gets the same small mesh.
  if grep -q "^subsection Mating roll" "$scene"; then
    cat >> "$1" <<PRM
subsection Mating roll
  subsection Mesh
    set Radial cells          = 3
    set Circumferential cells = 16
    set Global refinements    = 0
  end
end
PRM
  fi
}
make_prm serial.prm out_serial
make_prm parallel.prm out_parallel

echo "running: rollnip serial.prm"
"$rollnip" serial.prm > serial.log 2>&1 ||
  { cat serial.log; fail "the serial run failed"; }
pass "serial run finished"
# A deadlock must show as one, not only as ctest's timeout.
limit=120
guard=()
if command -v timeout > /dev/null; then
  guard=(timeout --kill-after=10 "$limit")
fi
echo "running: $mpiexec ${mpi_flags[*]} -np 2 rollnip parallel.prm"
rc=0
"${guard[@]}" "$mpiexec" "${mpi_flags[@]}" -np 2 "$rollnip" parallel.prm \
  > parallel.log 2>&1 || rc=$?
if [ "$rc" -ne 0 ]; then
  cat parallel.log
  if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then
    fail "the run on 2 MPI processes did not finish within $limit s (deadlock?)"
  fi
  fail "the run on 2 MPI processes failed (exit code $rc)"
fi
pass "run on 2 MPI processes finished"

# A contact scene writes one directory per nip, a pressure scene one result.
results=(.)
if [ -d out_serial/nip-01 ]; then
  results=()
  for d in out_serial/nip-[0-9]*; do results+=("$(basename "$d")"); done
  [ -f out_serial/nip_characteristic.csv ] ||
    fail "out_serial/nip_characteristic.csv missing"
fi
for dir in out_serial out_parallel; do
  for r in "${results[@]}"; do
    [ -f "$dir/$r/summary.txt" ] || fail "$dir/$r/summary.txt missing"
  done
done
first="${results[0]}"
[ "$(summary_value "out_serial/$first/summary.txt" mpi_processes)" -eq 1 ] ||
  fail "the serial run did not report mpi_processes = 1"
[ "$(summary_value "out_parallel/$first/summary.txt" mpi_processes)" -eq 2 ] ||
  fail "the parallel run did not report mpi_processes = 2"
pass "summary.txt reports mpi_processes = 1 and 2"
for r in "${results[@]}"; do
  [ "$(summary_value "out_serial/$r/summary.txt" status)" = converged ] ||
    fail "the serial run did not converge ($r)"
done
pass "status = converged (${#results[@]} result(s))"

# Everything except the timings and the process count must agree, and the
# work counters: the sums of two partitions differ in round-off, which can
# move an inner stopping test by one iteration (two rolls: 339 against 331
# assemblies, with every result within 1e-8).
# A covered mating roll's results sit in mating_roll/ of every nip.
if [ -d "out_serial/${results[0]}/mating_roll" ]; then
  n=${#results[@]}
  for ((i = 0; i < n; ++i)); do results+=("${results[$i]}/mating_roll"); done
fi
for dir in out_serial out_parallel; do
  for r in "${results[@]}"; do
    grep -v -E '^([a-z_]*wall_time_s|time_[a-z_]*_s|mpi_processes|threads|gmres_iterations|gmres_solves|assemblies|linear_solves|chord_steps) =' \
      "$dir/$r/summary.txt" > "$dir/$r/summary_compared.txt"
  done
done

# compare FILE [REL ABS]: numdiff of out_serial/FILE and out_parallel/FILE.
compare()
{
  local rel="${2:-1e-8}" abs="${3:-1e-12}"
  files_agree "$numdiff" "$rel" "$abs" "out_serial/$1" "out_parallel/$1" ||
    fail "$1 differs between 1 and 2 MPI processes"
  pass "$1: serial and 2 processes agree ($(wc -l < "out_serial/$1") lines, rel $rel, abs $abs)"
}

# The estimated errors (columns *_err_*) are differences of two solves, so
# the round-off of each (1e-8 of the value at most) is a larger part of
# them: they are compared apart, to 1e-3 of themselves or 1e-7 absolute
# (mm, MPa, N/mm, deg), far below any error they report.
split_errors()
{
  local file="$1" errors="$2" values="$3"
  awk -F, -v errors="$errors" -v values="$values" '
    NR == 1 { for (i = 1; i <= NF; ++i) is_error[i] = ($i ~ /_err_/) }
    {
      e = ""; v = ""
      for (i = 1; i <= NF; ++i)
        if (is_error[i]) e = e (e == "" ? "" : ",") $i
        else v = v (v == "" ? "" : ",") $i
      print e > errors; print v > values
    }' "$file"
}
for r in "${results[@]}"; do
  compare "$r/summary_compared.txt"
  compare "$r/outer_surface.csv"
  compare "$r/bond_surface.csv"
  if [ "$r" != . ] && [ -f "out_serial/$r/contact_pressure.csv" ]; then
    compare "$r/contact_pressure.csv"
  fi
done
if [ "$first" != . ]; then
  for dir in out_serial out_parallel; do
    split_errors "$dir/nip_characteristic.csv" "$dir/nip_errors.csv" \
      "$dir/nip_values.csv"
  done
  compare nip_values.csv
  compare nip_errors.csv 1e-3 1e-7
fi
for r in "${results[@]}"; do
  echo "$r serial:   P = $(summary_value "out_serial/$r/summary.txt" nip_load_P_N_per_mm) N/mm," \
    "u0 = $(summary_value "out_serial/$r/summary.txt" indentation_u0_mm) mm"
  echo "$r parallel: P = $(summary_value "out_parallel/$r/summary.txt" nip_load_P_N_per_mm) N/mm," \
    "u0 = $(summary_value "out_parallel/$r/summary.txt" indentation_u0_mm) mm"
done
