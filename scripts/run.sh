#!/usr/bin/env bash
# Sets everything up (scripts/setup.sh) and runs rollnip on one parameter file.
#
# Usage: bash scripts/run.sh [FILE.prm]     (default: parameters/batra1980.prm)
# A relative FILE.prm is taken from the directory you call this from; rollnip
# itself runs from the repository root, so relative paths inside the file
# (Output/Directory, Mesh/Mesh file) are relative to the repository root.
set -euo pipefail

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

prm="${1:-$repo_root/parameters/batra1980.prm}"
if [ ! -f "$prm" ]; then
  echo "run: error: parameter file '$prm' not found" >&2
  exit 1
fi
prm="$(cd "$(dirname "$prm")" && pwd)/$(basename "$prm")"

bash "$repo_root/scripts/setup.sh"

cd "$repo_root"
status=0
build/rollnip "$prm" || status=$?

# The output directory as rollnip resolved it (the last 'Directory' entry of
# the Output subsection, default 'output').
outdir="$(awk '
  /^[[:space:]]*subsection[[:space:]]+Output[[:space:]]*$/ { inside = 1; next }
  inside && /^[[:space:]]*end[[:space:]]*$/ { inside = 0 }
  inside && /^[[:space:]]*set[[:space:]]+Directory[[:space:]]*=/ {
    sub(/^[^=]*=[[:space:]]*/, ""); sub(/[[:space:]]*(#.*)?$/, ""); dir = $0 }
  END { print (dir == "" ? "output" : dir) }' "$prm")"
case "$outdir" in
  /*) ;;
  *) outdir="$repo_root/$outdir" ;;
esac

echo
if [ "$status" -eq 0 ]; then
  echo "run: finished; results are in $outdir"
else
  echo "run: rollnip stopped with exit status $status; whatever it wrote is in $outdir" >&2
fi
echo "     summary.txt, outer_surface.csv, bond_surface.csv, load_steps.csv,"
echo "     newton_log.csv; open solution.pvd in ParaView"
exit "$status"
