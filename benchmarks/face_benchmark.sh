#!/usr/bin/env bash
# Times the face model (doc/face.md) on parameters/crown.prm: the sweep that
# samples the cross-section's law P_2D(u0) (once per cross-section), and the
# face answer with that law read from its cache. One row per mesh level of
# the cross-section.
#
# Usage: bash benchmarks/face_benchmark.sh [LEVELS...]   (default: 1 2)
#
# Uses build/rollnip of this repository, or $ROLLNIP_BIN. Each level runs in
# a temporary directory: a first run sweeps the law (column 'sweep s', the
# sweep's own time from summary.txt), a second run reads it back (column
# 'cached run s': the wall time of the whole process, MPI start included;
# 'face solve s': the face's Newton solve alone, from summary.txt).
# Columns: level, cells of the cross-section, approaches swept, sweep s,
# cached run s, face solve s, Newton iterations, q centre/end.
set -euo pipefail

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
rollnip="$(realpath "${ROLLNIP_BIN:-$repo_root/build/rollnip}")"
[ -x "$rollnip" ] || { echo "face_benchmark: error: no executable '$rollnip'" >&2; exit 1; }
levels=("$@")
[ "${#levels[@]}" -gt 0 ] || levels=(1 2)
work="$(mktemp -d /tmp/rollnip-face-benchmark.XXXXXX)"
trap 'rm -rf "$work"' EXIT

value() { awk -F' = ' -v k="$2" '$1 == k {print $2}' "$1"; }

printf '%-6s %-7s %-11s %-8s %-13s %-13s %-7s %s\n' level cells approaches \
  'sweep s' 'cached run s' 'face solve s' Newton 'q centre/end'
for level in "${levels[@]}"; do
  dir="$work/level-$level"
  mkdir -p "$dir"
  cp "$repo_root/parameters/crown.prm" "$dir/crown.prm"
  printf '\nsubsection Mesh\n  set Global refinements = %s\nend\nsubsection Output\n  set Directory = output\nend\n' \
    "$level" >> "$dir/crown.prm"
  (cd "$dir" && "$rollnip" crown.prm > sweep.txt)
  sweep="$(value "$dir/output/summary.txt" law_sweep_seconds)"
  start="$(date +%s.%N)"
  (cd "$dir" && "$rollnip" crown.prm > cached.txt)
  end="$(date +%s.%N)"
  s="$dir/output/summary.txt"
  [ "$(value "$s" law_from_cache)" = yes ] ||
    { echo "face_benchmark: error: the second run did not read the cache" >&2; exit 1; }
  cells="$(grep -m1 -o '[0-9]* cells' "$dir/sweep.txt" | cut -d' ' -f1)"
  printf '%-6s %-7s %-11s %-8.3g %-13.3g %-13.3g %-7s %.6g\n' "$level" "$cells" \
    "$(value "$s" law_samples)" "$sweep" "$(echo "$end - $start" | bc)" \
    "$(value "$s" face_solve_seconds)" "$(value "$s" newton_iterations)" \
    "$(value "$s" line_load_centre_over_end)"
done
