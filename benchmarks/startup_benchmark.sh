#!/usr/bin/env bash
# Start-up cost of rollnip: the wall time of `rollnip --help` (the shared
# libraries alone; the command line is read before MPI starts) and of a
# run up to its first solve (the "Mesh:" line of
# parameters/parabolic_pressure.prm, level 0), median of N runs each, with
# the settings rollnip makes for a process started without mpirun
# (OMPI_MCA_ess_singleton_isolated = 1, OMPI_MCA_pml = ob1) and with Open
# MPI's own defaults for comparison (the environment overrides them); the
# CPU time (user + system) beside the wall time, which other jobs on the
# machine stretch. The last row is the floor: an empty program linked
# against the libdeal.II that rollnip loads, and nothing else (built here
# with c++), whose start-up is the dynamic loader's alone.
#
# Usage: bash benchmarks/startup_benchmark.sh [N]     (default N = 5)
#        ROLLNIP_BIN=path/to/rollnip bash benchmarks/startup_benchmark.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
rollnip="${ROLLNIP_BIN:-$root/build/rollnip}"
n="${1:-5}"
[ -x "$rollnip" ] || { echo "startup_benchmark: error: $rollnip not found; build it with: bash scripts/setup.sh" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cat "$root/parameters/parabolic_pressure.prm" - > "$work/run.prm" <<PRM
subsection Mesh
  set Global refinements = 0
end
subsection Output
  set Directory = $work/out
  set Write VTU = false
  set Print timing = false
end
PRM

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# seconds from the start of COMMAND to its first output line matching
# PATTERN (or to its end, for an empty pattern), and the CPU seconds of
# the whole COMMAND ("WALL CPU").
until_line() {
  local pattern="$1"; shift
  python3 - "$pattern" "$@" <<'PY'
import resource, subprocess, sys, time
pattern, cmd = sys.argv[1], sys.argv[2:]
t0 = time.perf_counter()
p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
t = None
for line in p.stdout:
    if pattern and t is None and line.startswith(pattern):
        t = time.perf_counter() - t0
p.wait()
u = resource.getrusage(resource.RUSAGE_CHILDREN)
print(f"{(t if t is not None else time.perf_counter() - t0):.3f} "
      f"{u.ru_utime + u.ru_stime:.3f}")
PY
}

defaults=(env OMPI_MCA_ess_singleton_isolated=0 OMPI_MCA_pml=ob1,cm,ucx)
row() {
  local label="$1" pattern="$2"; shift 2
  local own cpu mpi
  own="$(for _ in $(seq "$n"); do until_line "$pattern" "$@"; done)"
  cpu="$(awk '{ print $2 }' <<<"$own" | median)"
  own="$(awk '{ print $1 }' <<<"$own" | median)"
  if [ "$1" = "$floor" ]; then
    mpi="-"
  else
    mpi="$(for _ in $(seq "$n"); do until_line "$pattern" "${defaults[@]}" "$@"; done | awk '{ print $1 }' | median)"
  fi
  printf '| %s | %s | %s | %s |\n' "$label" "$own" "$cpu" "$mpi"
}

# The floor: nothing but libdeal.II (and what it pulls in) to load.
deal="$(ldd "$rollnip" | awk '/libdeal[.]ii/ { print $3; exit }')"
floor="$work/empty_with_deal"
echo 'int main() { return 0; }' > "$work/empty.cc"
c++ -O2 "$work/empty.cc" -o "$floor" -Wl,--no-as-needed "$deal"

echo "machine: $(nproc) cores, $(uname -m); rollnip: $rollnip; median of $n runs"
echo "$(ldd "$floor" | grep -c '=>') shared libraries loaded by a program linked to $deal"
echo
echo "| what | wall s, rollnip's MPI settings | CPU s, whole command | wall s, Open MPI defaults |"
echo "|---|---|---|---|"
row "rollnip --help" "" "$rollnip" --help
row "start to the first solve (Mesh: line)" "Mesh:" "$rollnip" "$work/run.prm"
row "whole run, parabolic_pressure.prm level 0" "" "$rollnip" "$work/run.prm"
row "empty program linked to libdeal.II alone" "" "$floor"
