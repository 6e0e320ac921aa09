#!/usr/bin/env bash
# Strong scaling and memory of the 3D plane-strain slice
# (parameters/slice_3d.prm, doc/three_d.md): the sizes below on 1 and 2
# MPI processes, and on 4 with --oversubscribe (more ranks than cores on a
# 2-core machine: flagged "yes" in the table, not a scaling figure). One
# table row per run; the same rows go to benchmarks/results/scaling_3d.csv
# (or $SCALING_CSV). Every size runs with each linear solver of SOLVERS
# (Linear solver/Method: direct, one MUMPS factorisation per Newton step,
# or gmres-amg, GMRES with the block AMG preconditioner). Each run prints
# its Newton log (Output/Verbosity = detailed) to a temporary file whose
# name goes to standard error: `tail -f` it to watch a long run.
#
# Usage: bash benchmarks/scaling_3d.sh [LEVEL:LAYERS ...]
#   default sizes: 3:2 (about 0.10 M DoFs), 4:2 (0.41 M), 4:4 (0.71 M);
#   4:6 is 1.0 M, 5:2 1.6 M, 5:3 2.2 M
# Environment: ROLLNIP_BIN (default build/rollnip), PROCESSES (default
# "1 2 4"), SOLVERS (default "direct gmres-amg"), U0 (the approaches, default "0.5" mm: one approach step, so
# that a run is a few Newton steps), MPIEXEC (default mpirun),
# RUN_TIMEOUT (seconds per run, default 900), ELEMENT
# (Discretization/Element: Q1-P0, the default, or Q2-P1; Q2-P1 has about
# 1.6 times the DoFs of Q1-P0 at one level lower: 3:2 is 0.63 M).
#
# Columns:
#   level, layers   Mesh/Global refinements, Three d/Layers
#   DoFs            n_dofs of summary.txt
#   solver          Linear solver/Method
#   np, oversub     MPI processes; "yes" when np > nproc
#   wall s          elapsed time of the whole command (mpirun, start-up,
#                   mesh, the sweep, output), /usr/bin/time %e
#   sweep s         wall_time_s of summary.txt (rollnip's own clock)
#   CPU s           user + system CPU time summed over the ranks
#                   (/usr/bin/time %U %S around each rank): on a machine
#                   shared with other jobs the wall time is an upper bound,
#                   the CPU time is the work done
#   Newton          Newton steps summed over the approaches (slice_3d.csv)
#   GMRES           GMRES iterations summed over them (0 for direct)
#   peak MB/rank    largest peak resident memory of one rank
#                   (/usr/bin/time %M around each rank)
#   total MB        sum of the ranks' peaks (an upper bound: the peaks
#                   need not coincide)
#   P N/mm          nip load at the last approach (equal across np and
#                   solvers to the solver tolerance)
#   load            the 1-minute load average at the end of the run
#                   (/proc/loadavg; above the cores: shared machine)
set -euo pipefail

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
rollnip="$(realpath "${ROLLNIP_BIN:-$repo_root/build/rollnip}")"
mpiexec="${MPIEXEC:-mpirun}"
processes="${PROCESSES:-1 2 4}"
solvers="${SOLVERS:-direct gmres-amg}"
u0="${U0:-0.5}"
run_timeout="${RUN_TIMEOUT:-900}"
element="${ELEMENT:-Q1-P0}"
csv="${SCALING_CSV:-$repo_root/benchmarks/results/scaling_3d.csv}"
[ -x "$rollnip" ] || { echo "scaling_3d: error: no executable '$rollnip'" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "scaling_3d: error: needs GNU time (/usr/bin/time)" >&2; exit 1; }
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(3:2 4:2 4:4)
if [ "$(id -u)" -eq 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
cores="$(nproc)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

value() { awk -F' = ' -v k="$2" '$1 == k { print $2 }' "$1"; }

# Each rank runs under its own /usr/bin/time, so that its peak resident
# memory lands in mem.<rank> (Open MPI's or MPICH's rank variable); the
# time limit sits below time, which does not pass signals on to rollnip.
cat > "$work/rank.sh" <<'RANK'
#!/usr/bin/env bash
rank="${OMPI_COMM_WORLD_RANK:-${PMI_RANK:-0}}"
exec /usr/bin/time -f "%M %U %S" -o "$MEM_DIR/mem.$rank" \
  timeout --signal=KILL "$RUN_TIMEOUT" "$@"
RANK
chmod +x "$work/rank.sh"

mkdir -p "$(dirname "$csv")"
echo "element,level,layers,dofs,solver,processes,oversubscribed,wall_time_s,sweep_time_s,cpu_time_s,newton_steps,gmres_iterations,peak_rss_per_rank_MB,peak_rss_total_MB,P_N_per_mm,u0_mm,load_average" > "$csv"
echo "element: $element"
printf '%5s %6s %9s %9s %3s %7s %8s %8s %8s %6s %6s %12s %9s %10s %5s\n' level layers DoFs solver np oversub "wall s" "sweep s" "CPU s" Newton GMRES "peak MB/rank" "total MB" "P N/mm" load
for size in "${sizes[@]}"; do
  level="${size%%:*}"
  layers="${size##*:}"
  for solver in $solvers; do
  for np in $processes; do
    out="$work/out"
    rm -rf "$out" "$work/mem"
    mkdir -p "$work/mem"
    prm="$work/run.prm"
    cp "$repo_root/parameters/slice_3d.prm" "$prm"
    cat >> "$prm" <<PRM
subsection Mesh
  set Global refinements = $level
end
subsection Three d
  set Layers = $layers
end
subsection Contact
  set Values = $u0
end
subsection Linear solver
  set Method = $solver
end
subsection Discretization
  set Element = $element
end
subsection Output
  set Directory = $out
  set Write VTU = false
  set Verbosity = detailed
end
PRM
    oversub=no
    launcher=()
    if [ "$np" -gt 1 ]; then
      launcher=("$mpiexec" -np "$np")
      if [ "$np" -gt "$cores" ]; then
        oversub=yes
        launcher+=(--oversubscribe)
      fi
    fi
    # The Newton log (Output/Verbosity = detailed) shows a long run's
    # progress, step by step, while it runs.
    echo "scaling_3d: $element, level $level, $layers layers, $solver, $np processes: Newton log in $work/log.txt" >&2
    rc=0
    MEM_DIR="$work/mem" RUN_TIMEOUT="$run_timeout" \
      /usr/bin/time -f %e -o "$work/elapsed" \
      timeout --kill-after=10 "$((run_timeout + 30))" \
      "${launcher[@]}" "$work/rank.sh" "$rollnip" "$prm" > "$work/log.txt" 2>&1 || rc=$?
    if [ "$rc" -ne 0 ]; then
      tail -n 5 "$work/log.txt" >&2
      echo "scaling_3d: $element, level $level, $layers layers, $solver, $np processes: failed (exit $rc; 137 or 124: stopped after ${run_timeout} s)" >&2
      echo "$element,$level,$layers,,$solver,$np,$oversub,,,,,,,,,$u0,$(cut -d' ' -f1 /proc/loadavg)" >> "$csv"
      continue
    fi
    s="$out/summary.txt"
    dofs="$(value "$s" n_dofs)"
    sweep="$(value "$s" wall_time_s)"
    P="$(value "$s" nip_load_P_N_per_mm)"
    newton="$(awk -F, 'NR > 1 { n += $6 } END { print n }' "$out/slice_3d.csv")"
    gmres="$(awk -F, 'NR > 1 { n += $9 } END { print n }' "$out/slice_3d.csv")"
    load="$(cut -d' ' -f1 /proc/loadavg)"
    elapsed="$(tail -n 1 "$work/elapsed")"
    read -r peak total cpu < <(cat "$work"/mem/mem.* | awk '$1 ~ /^[0-9]+$/ { if ($1 > m) m = $1; t += $1; c += $2 + $3 } END { printf "%.0f %.0f %.1f\n", m / 1024, t / 1024, c }')
    printf '%5d %6d %9d %9s %3d %7s %8.1f %8.1f %8.1f %6d %6d %12d %9d %10.6f %5s\n' \
      "$level" "$layers" "$dofs" "$solver" "$np" "$oversub" "$elapsed" "$sweep" "$cpu" "$newton" "$gmres" "$peak" "$total" "$P" "$load"
    echo "$element,$level,$layers,$dofs,$solver,$np,$oversub,$elapsed,$sweep,$cpu,$newton,$gmres,$peak,$total,$P,$u0,$load" >> "$csv"
  done
  done
done
echo "CSV: $csv"
