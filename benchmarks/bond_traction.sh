#!/bin/bash
# Convergence of the bond and interface tractions on an engineer's scene:
# 70 Shore A, a 20 mm cover on a 400 mm roll against a 300 mm steel roll at
# 40 kN/m, and the same with a layered cover (5 mm of 90 Shore A on 15 mm
# of 60 Shore A). Default mesh (4 x 16 coarse cells, nip-fitted) at Q1-P0
# levels 0 to 3 (1 is the default); the reference is Q2-P1 at level 4.
# Prints one Markdown table per cover: bond sigma_rr min and
# |sigma_rtheta| max, the interface's sigma_nn min and |sigma_nt| max
# [MPa], and the relative error of each against the reference.
#
# Usage: [COVERS="single layered"] bash benchmarks/bond_traction.sh
#            [REFERENCE_LEVEL]
# Uses build/rollnip or $ROLLNIP_BIN; about 10 minutes on one core.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
rollnip=${ROLLNIP_BIN:-$root/build/rollnip}
reference_level=${1:-4}
[ -x "$rollnip" ] || { echo "bond_traction.sh: no $rollnip" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# run NAME ELEMENT LEVEL MATERIAL_LINES -> prints the summary values
run() {
  local dir=$tmp/$1
  cat >"$tmp/$1.prm" <<EOF
subsection Geometry
  set Roll diameter   = 400
  set Cover thickness = 20
end
subsection Material
$4
  set Hardness scale = Shore A
end
subsection Contact
  set Mode              = load
  set Load unit         = kN/m
  set Values            = 40
  set Indenter diameter = 300
end
subsection Mesh
  set Global refinements = $3
end
subsection Discretization
  set Element = $2
end
subsection Accuracy
  set Error estimate = false
end
subsection Output
  set Directory = $dir
  set Write VTU = false
end
EOF
  "$rollnip" "$tmp/$1.prm" >"$tmp/$1.log" 2>&1 ||
    { echo "bond_traction.sh: $1 failed, see its log:" >&2; tail "$tmp/$1.log" >&2; exit 1; }
  # One nip: its summary.txt is in the output directory itself.
  local s=$dir/nip-01/summary.txt
  [ -f "$s" ] || s=$dir/summary.txt
  local keys="bond_sigma_rr_min_MPa bond_sigma_rtheta_max_abs_MPa interface_1_sigma_nn_min_MPa interface_1_sigma_nt_max_abs_MPa"
  for k in $keys; do
    grep -m1 "^$k = " "$s" | sed 's/.* = //' || echo nan
  done | paste -sd' '
  grep -m1 "^Mesh:" "$tmp/$1.log" | sed 's/Mesh: [0-9]* cells, \([0-9]*\) DoFs.*/\1/'
}

table() {
  local name=$1 material=$2
  local out ref
  out=$(run "$name-ref" Q2-P1 "$reference_level" "$material")
  ref=$(echo "$out" | head -1)
  echo
  echo "$name cover; reference Q2-P1 level $reference_level: $ref"
  echo
  echo "| level | DoFs | bond sigma_rr min | err | bond sigma_rtheta max | err | interface sigma_nn min | err | interface sigma_nt max | err |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  for level in 0 1 2 3; do
    local out values dofs
    out=$(run "$name-$level" Q1-P0 "$level" "$material")
    values=$(echo "$out" | head -1)
    dofs=$(echo "$out" | tail -1)
    python3 - "$level" "$dofs" "$values" "$ref" <<'EOF'
import sys
level, dofs, values, ref = sys.argv[1], sys.argv[2], sys.argv[3].split(), sys.argv[4].split()
cells = [level, dofs]
for v, r in zip(values, ref):
    if v == "nan" or r == "nan":
        cells += ["-", "-"]
    else:
        cells += [f"{float(v):.5g}", f"{abs(float(v) - float(r)) / abs(float(r)):.1e}"]
print("| " + " | ".join(cells) + " |")
EOF
  done
}

for cover in ${COVERS:-single layered}; do
  case $cover in
    single) table single "  set Hardness = 70" ;;
    layered) table layered "  set Hardness = 60, 90
  set Layer thicknesses = 15, 5" ;;
  esac
done
