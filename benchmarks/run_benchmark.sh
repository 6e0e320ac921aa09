#!/usr/bin/env bash
# Times rollnip on the default pressure scene (parameters/parabolic_pressure.prm) at
# global refinements 0, 1, 2 and 3, and prints one table row per level.
#
# Usage: bash benchmarks/run_benchmark.sh [N]     (N timed runs per level, default 3)
#
# Uses build/rollnip of this repository (build it with: bash scripts/setup.sh),
# or the executable named by $ROLLNIP_BIN (to time another build).
# Each run reads a temporary copy of the .prm with 'Mesh/Global refinements'
# changed and VTU output switched off (Output/Write VTU = false), writing into a
# temporary directory. One extra run per level with VTU on (every step)
# measures what the ParaView output costs (column 'VTU out s').
#
# Columns (times in seconds; the breakdown is that of the run with the median
# total):
#   setup s, assembly s, linear solve s, output s   summary.txt: time_*_s
#   solve s    summary.txt: last_solve_wall_time_s (the load stepping)
#   total s    wall time of the whole process, measured here (median of N)
#   ratio      solve s / (one assembly + one factorisation), with
#              one assembly      = time_assembly_s / assemblies (tangent and
#                                  residual-only assemblies together)
#              one factorisation = time_linear_solve_s / linear_solves
#              i.e. how many "Newton iterations' worth" of work the solve costs
# The table is also written as CSV to benchmarks/results/.
set -euo pipefail

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo_root"

n_repeats="${1:-3}"
case "$n_repeats" in
  '' | *[!0-9]* | 0)
    echo "run_benchmark: error: N must be a positive integer, got '$n_repeats'" >&2
    exit 1
    ;;
esac

base_prm="parameters/parabolic_pressure.prm"
rollnip="${ROLLNIP_BIN:-build/rollnip}"
levels=(0 1 2 3)

if [ ! -x "$rollnip" ]; then
  echo "run_benchmark: error: $rollnip not found; build it with: bash scripts/setup.sh" >&2
  exit 1
fi

tmp="$(mktemp -d "${TMPDIR:-/tmp}/rollnip-bench.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

# summary.txt value of KEY in FILE.
get() { awk -F' = ' -v k="$2" '$1 == k { print $2; exit }' "$1"; }

# Writes the parameter file for refinement $1, output directory $2, VTU $3.
make_prm() {
  local level="$1" outdir="$2" vtu="$3" prm="$tmp/ref$1-$3.prm"
  if grep -Eq '^[[:space:]]*set[[:space:]]+Global refinements[[:space:]]*=' "$base_prm"; then
    sed -E "s/^([[:space:]]*set[[:space:]]+Global refinements[[:space:]]*=).*/\1 $level/" \
      "$base_prm" >"$prm"
  else
    { cat "$base_prm"; printf 'subsection Mesh\n  set Global refinements = %s\nend\n' "$level"; } >"$prm"
  fi
  # A subsection may be entered again; later entries override earlier ones.
  cat >>"$prm" <<PRM

# --- benchmark overrides ---
subsection Output
  set Directory      = $outdir
  set Write VTU      = $vtu
  set VTU every step = true
end
PRM
  echo "$prm"
}

# Runs rollnip on $1 and prints the wall time of the process in seconds.
timed_run() {
  local prm="$1" log="$2" t0 t1
  t0="$(date +%s.%N)"
  if ! "$rollnip" "$prm" >"$log" 2>&1; then
    echo "run_benchmark: error: rollnip failed on $prm; its output:" >&2
    tail -n 30 "$log" >&2
    exit 1
  fi
  t1="$(date +%s.%N)"
  awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.4f\n", b - a }'
}

cpu_model="$( (grep -m1 'model name' /proc/cpuinfo 2>/dev/null || true) | sed 's/^[^:]*:[[:space:]]*//')"
[ -n "$cpu_model" ] || cpu_model="$(uname -m)"
commit="$(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
if [ -n "$(git status --porcelain --untracked-files=no 2>/dev/null || true)" ]; then
  commit="$commit+local changes"
fi
stamp="$(date +%Y-%m-%dT%H:%M:%S%z)"

echo "rollnip benchmark: $base_prm, refinements ${levels[*]}, $n_repeats run(s) per level, VTU off"
echo "machine: nproc = $(nproc), CPU = $cpu_model"
echo "date: $stamp, commit: $commit, 1 MPI process"
echo

mkdir -p benchmarks/results
csv="benchmarks/results/benchmark-$(date +%Y%m%d-%H%M%S).csv"
echo "refinement,cells,dofs,load_steps,newton_iterations,setup_s,assembly_s,linear_solve_s,output_s,solve_s,total_s,total_min_s,total_max_s,ratio_solve_to_assembly_plus_factorisation,vtu_output_s" >"$csv"

header_fmt="%3s %7s %8s %6s %7s %8s %9s %9s %8s %8s %8s %7s %9s\n"
row_fmt="%3s %7s %8s %6s %7s %8.3f %9.3f %9.3f %8.3f %8.3f %8.3f %7.1f %9.3f\n"
# shellcheck disable=SC2059  # the formats are the constants above
printf "$header_fmt" ref cells DOFs steps Newton "setup s" "assembly s" "lin.sol s" \
  "output s" "solve s" "total s" ratio "VTU out s"

for level in "${levels[@]}"; do
  prm="$(make_prm "$level" "$tmp/out-$level" false)"
  : >"$tmp/runs-$level"
  for ((i = 1; i <= n_repeats; ++i)); do
    rm -rf "$tmp/out-$level"
    total="$(timed_run "$prm" "$tmp/log-$level-$i")"
    cp "$tmp/out-$level/summary.txt" "$tmp/summary-$level-$i"
    status="$(get "$tmp/summary-$level-$i" status)"
    if [ "$status" != converged ]; then
      echo "run_benchmark: warning: refinement $level run $i: status = $status" >&2
    fi
    echo "$total $i" >>"$tmp/runs-$level"
  done
  # The run with the median total (the lower middle one for even N).
  sort -n "$tmp/runs-$level" >"$tmp/sorted-$level"
  median_line="$(sed -n "$(((n_repeats + 1) / 2))p" "$tmp/sorted-$level")"
  total="${median_line% *}"
  run="${median_line#* }"
  total_min="$(head -n1 "$tmp/sorted-$level" | cut -d' ' -f1)"
  total_max="$(tail -n1 "$tmp/sorted-$level" | cut -d' ' -f1)"
  s="$tmp/summary-$level-$run"

  # One more run with VTU on, for the cost of the ParaView output.
  vtu_prm="$(make_prm "$level" "$tmp/vtu-$level" true)"
  timed_run "$vtu_prm" "$tmp/log-vtu-$level" >/dev/null
  vtu_output="$(get "$tmp/vtu-$level/summary.txt" time_output_s)"
  rm -rf "$tmp/vtu-$level"

  cells="$(get "$s" cells)"
  dofs="$(get "$s" dofs)"
  steps="$(get "$s" load_steps)"
  newton="$(get "$s" newton_iterations)"
  assemblies="$(get "$s" assemblies)"
  solves="$(get "$s" linear_solves)"
  t_setup="$(get "$s" time_setup_s)"
  t_asm="$(get "$s" time_assembly_s)"
  t_lin="$(get "$s" time_linear_solve_s)"
  t_out="$(get "$s" time_output_s)"
  t_solve="$(get "$s" last_solve_wall_time_s)"
  ratio="$(awk -v w="$t_solve" -v a="$t_asm" -v na="$assemblies" -v l="$t_lin" -v nl="$solves" \
    'BEGIN { u = (na > 0 ? a / na : 0) + (nl > 0 ? l / nl : 0); printf "%.2f\n", (u > 0 ? w / u : 0) }')"

  # shellcheck disable=SC2059
  printf "$row_fmt" "$level" "$cells" "$dofs" "$steps" "$newton" "$t_setup" "$t_asm" \
    "$t_lin" "$t_out" "$t_solve" "$total" "$ratio" "$vtu_output"
  echo "$level,$cells,$dofs,$steps,$newton,$t_setup,$t_asm,$t_lin,$t_out,$t_solve,$total,$total_min,$total_max,$ratio,$vtu_output" >>"$csv"
done

echo
echo "CSV: $repo_root/$csv"
