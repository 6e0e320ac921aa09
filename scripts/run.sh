#!/usr/bin/env bash
# Sets everything up (scripts/setup.sh) and runs rollnip on one parameter file.
#
# Usage: bash scripts/run.sh [FILE.prm]     (default: parameters/batra1980.prm)
# A relative FILE.prm, and relative paths inside it (Output/Directory,
# Mesh/Mesh file), are taken from the directory you call this from, as when
# you run build/rollnip there yourself.
# After a successful run it draws the figures with scripts/plot_results.sh
# into OUTPUT_DIR/plots/ (E = 6 (C1 + C2) for the nondimensional contact
# pressure is taken from the file's Material section when both are set there).
#
# ROLLNIP_BIN=path/to/rollnip runs that binary instead of build/rollnip and
# skips the setup (packages and build), as the tests do.
set -euo pipefail

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

prm="${1:-$repo_root/parameters/batra1980.prm}"
if [ ! -f "$prm" ]; then
  echo "run: error: parameter file '$prm' not found" >&2
  exit 1
fi
prm="$(cd "$(dirname "$prm")" && pwd)/$(basename "$prm")"

rollnip="${ROLLNIP_BIN:-}"
if [ -z "$rollnip" ]; then
  bash "$repo_root/scripts/setup.sh"
  rollnip="$repo_root/build/rollnip"
fi

status=0
"$rollnip" "$prm" || status=$?

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
  *) outdir="$PWD/$outdir" ;;
esac

echo
if [ "$status" -eq 0 ]; then
  echo "run: finished; results are in $outdir"
else
  echo "run: rollnip stopped with exit status $status; whatever it wrote is in $outdir" >&2
fi
echo "     summary.txt, outer_surface.csv, bond_surface.csv, load_steps.csv,"
echo "     newton_log.csv (per nip in nip-NN/ for a sweep); open solution.pvd in ParaView"
[ "$status" -eq 0 ] || exit "$status"

# Young's modulus E = 6 (C1 + C2) from the Material section, if both constants
# are plain numbers there (otherwise the E-scaled figure is left out).
young="$(awk '
  /^[[:space:]]*subsection[[:space:]]+Material[[:space:]]*$/ { inside = 1; next }
  inside && /^[[:space:]]*end[[:space:]]*$/ { inside = 0 }
  inside && /^[[:space:]]*set[[:space:]]+C[12][[:space:]]*=/ {
    name = $2; sub(/=.*/, "", name)
    sub(/^[^=]*=[[:space:]]*/, ""); sub(/[[:space:]]*(#.*)?$/, ""); c[name] = $0 }
  END {
    number = "^[-+]?[0-9]*[.]?[0-9]+([eE][-+]?[0-9]+)?$"
    if (c["C1"] ~ number && c["C2"] ~ number && c["C1"] + c["C2"] > 0)
      printf "%.10g\n", 6 * (c["C1"] + c["C2"]) }' "$prm")"

echo
plot_status=0
ROLLNIP_E_MPA="$young" bash "$repo_root/scripts/plot_results.sh" "$outdir" || plot_status=$?
if [ "$plot_status" -eq 0 ]; then
  echo "run: plots (PNG and SVG) are in $outdir/plots"
else
  echo "run: the run succeeded but plotting failed (exit status $plot_status); the results are in $outdir" >&2
fi
exit "$plot_status"
