#!/bin/bash
# What the error estimate costs on the default run: parameters/batra1980.prm
# (nip angle, Q1-P0 level 2, three nips with their linear companions,
# Output/Write VTU = false, one thread) with Accuracy/Error estimate = true
# and false, run in turn N times. Prints a Markdown table of the median CPU
# and wall time of the whole process [s] for each.
#
# Usage: [ROLLNIP_BEFORE=<another build>] bash benchmarks/estimate_cost.sh [N]
# Uses build/rollnip or $ROLLNIP_BIN; ROLLNIP_BEFORE adds rows for another
# build, run in the same turns. N = 5 by default (about a minute).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
rollnip=${ROLLNIP_BIN:-$root/build/rollnip}
n=${1:-5}
[ -x "$rollnip" ] || { echo "estimate_cost.sh: no $rollnip" >&2; exit 1; }
binaries=("$rollnip")
if [ -n "${ROLLNIP_BEFORE:-}" ]; then
  [ -x "$ROLLNIP_BEFORE" ] || { echo "estimate_cost.sh: no $ROLLNIP_BEFORE" >&2; exit 1; }
  binaries+=("$ROLLNIP_BEFORE")
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for estimate in true false; do
  sed "s#^ *set Directory .*#  set Directory = $tmp/out#" \
    "$root/parameters/batra1980.prm" > "$tmp/$estimate.prm"
  printf 'subsection Output\n  set Write VTU = false\nend\nsubsection Accuracy\n  set Error estimate = %s\nend\n' \
    "$estimate" >> "$tmp/$estimate.prm"
done
# One line per run: binary index, estimate, CPU s, wall s.
for _ in $(seq "$n"); do
  for b in "${!binaries[@]}"; do
    for estimate in true false; do
      DEAL_II_NUM_THREADS=1 /usr/bin/time -o "$tmp/time" -f "%U %S %e" \
        "${binaries[$b]}" "$tmp/$estimate.prm" > /dev/null 2>&1 ||
        { echo "estimate_cost.sh: ${binaries[$b]} failed" >&2; exit 1; }
      awk -v b="$b" -v e="$estimate" '{ print b, e, $1 + $2, $3 }' \
        "$tmp/time" >> "$tmp/runs"
    done
  done
done
median() { sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
echo "| build | error estimate | CPU s (median of $n) | wall s |"
echo "|---|---|---|---|"
for b in "${!binaries[@]}"; do
  for estimate in true false; do
    cpu=$(awk -v b="$b" -v e="$estimate" '$1 == b && $2 == e { print $3 }' "$tmp/runs" | median)
    wall=$(awk -v b="$b" -v e="$estimate" '$1 == b && $2 == e { print $4 }' "$tmp/runs" | median)
    echo "| ${binaries[$b]} | $estimate | $cpu | $wall |"
  done
done
