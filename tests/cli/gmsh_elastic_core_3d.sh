#!/usr/bin/env bash
# The elastic steel core (Three d/Core = elastic) under a gmsh cover: the
# user's quadrilateral cross-section of the cover, with the tube meshed
# inside it through the bond's own nodes, extruded along the face.
#
# Usage: bash gmsh_elastic_core_3d.sh ROLLNIP GMSH SCENE STRUCTURED_GEO FREE_GEO
#   SCENE           parameters/elastic_core_3d.prm (180 deg, 6 x 16 cells
#                   graded 10, a 500 mm half face on a tube to 600 mm)
#   STRUCTURED_GEO  meshes/quarter_roll.geo
#   FREE_GEO        meshes/quarter_roll_free.geo
#
# 1. quarter_roll.geo drawn with SCENE's builtin cells (Sector 180, NR 6,
#    NTheta 16, GradeTheta 10) is the builtin cross-section to gmsh's
#    round-off (about 1e-7 mm), so the tube under it is the builtin tube:
#    at mesh levels 0 and 1 P, b, the active nodes, the line load q(z) at
#    every plane and the core's bending line v(z) at every plane to the
#    journal must be the builtin run's to 1e-6 (the discretisation error
#    is above 1e-3).
# 2. quarter_roll_free.geo (Sector 180): unstructured quadrilaterals, no
#    bond node where the builtin mesh has one. At level 0 (Q1-P0) its P
#    and the core's deflection at the middle of the face must lie within
#    Q1-P0's discretisation error of a reference made with the other
#    element: Q2-P1 on the builtin mesh at level 0 (67 085 DoFs), pinned
#    below (the same cover on the gmsh mesh with Q2-P1 gives P 0.06 % and
#    v(0) 0.14 % from it). Q1-P0's two linear cells through the tube's
#    wall bend too stiffly: on the builtin mesh they are 1.7 % off in P
#    and 4.3 % in v(0) at level 0; the tolerances are 2 % and 6 %. A
#    cover not joined to the tube (its bond nodes not shared) would be
#    off by far more.
# 3. --validate on the unstructured scene prints the run's cells and DoFs.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 5 ] ||
  fail "usage: gmsh_elastic_core_3d.sh ROLLNIP GMSH SCENE STRUCTURED_GEO FREE_GEO"
rollnip="$(realpath "$1")"
gmsh="$2"
scene="$(realpath "$3")"
structured_geo="$(realpath "$4")"
free_geo="$(realpath "$5")"
require_executable rollnip "$rollnip"
require_executable "gmsh (needed to mesh the cross-sections)" "$gmsh"
start_test gmsh_elastic_core_3d

gmsh_mesh "$gmsh" 2 "$structured_geo" structured.msh -setnumber R1 47.2 -setnumber R0 60.7 \
  -setnumber Sector 180 -setnumber NR 6 -setnumber NTheta 16 \
  -setnumber GradeTheta 10
gmsh_mesh "$gmsh" 2 "$free_geo" free.msh -setnumber Sector 180

# run NAME LEVEL [MESH_FILE]: SCENE at LEVEL, builtin or on MESH_FILE.
run()
{
  cp "$scene" "$1.prm"
  {
    printf '\nsubsection Mesh\n  set Global refinements = %s\n' "$2"
    if [ $# -eq 3 ]; then
      printf '  set Source = gmsh\n  set Mesh file = %s\n' "$3"
    fi
    printf 'end\n'
    quiet_output "out_$1"
  } >> "$1.prm"
  run_named "$1"
}

# along_axis_agree A B FILE COLUMN LABEL: every row of FILE in out_A and
# out_B, z to 1e-7 mm and COLUMN to 1e-6 relative.
along_axis_agree()
{
  local a="out_$1/$3" b="out_$2/$3" column="$4" label="$5" rows k
  rows="$(wc -l < "$a")"
  [ "$rows" -gt 2 ] || fail "$label: $3 has no planes"
  [ "$rows" -eq "$(wc -l < "$b")" ] || fail "$label: $3 has other planes"
  for k in $(seq 1 $((rows - 1))); do
    check_close "$label, $3 row $k: z_mm" "$(csv_value "$b" z_mm $k)" \
      "$(csv_value "$a" z_mm $k)" 1e-7
    check_rel_close "$label, $3 row $k: $column" \
      "$(csv_value "$b" "$column" $k)" "$(csv_value "$a" "$column" $k)" 1e-6
  done
}

for level in 0 1; do
  run builtin_$level $level
  run structured_$level $level structured.msh
  label="level $level, gmsh against builtin"
  for column in P_N_per_mm half_chord_b_mm active_nodes; do
    tolerance=1e-6
    [ "$column" = active_nodes ] && tolerance=0
    check_rel_close "$label: $column" \
      "$(csv_value out_structured_$level/slice_3d.csv $column 1)" \
      "$(csv_value out_builtin_$level/slice_3d.csv $column 1)" $tolerance
  done
  along_axis_agree builtin_$level structured_$level line_load_along_axis.csv \
    line_load_N_per_mm "$label"
  along_axis_agree builtin_$level structured_$level \
    core_deflection_along_axis.csv core_deflection_v_mm "$label"
done

run free_0 0 free.msh
REF_P=4.7417835
REF_V=0.21693707
check_rel_close "unstructured gmsh cover, level 0: P against Q2-P1" \
  "$(summary_value out_free_0/summary.txt nip_load_P_N_per_mm)" "$REF_P" 2e-2
check_rel_close "unstructured gmsh cover, level 0: v(0) against Q2-P1" \
  "$(summary_value out_free_0/summary.txt core_deflection_middle_mm)" \
  "$REF_V" 6e-2
echo "unstructured cover: $(summary_value out_free_0/summary.txt n_cells) cells at level 0"

# --validate builds the same 3D body (cover and tube) without solving: its
# cells and DoFs are the run's.
"$rollnip" --validate free_0.prm > validate.txt 2> validate.err ||
  { cat validate.err; fail "--validate free_0.prm failed"; }
line="$(grep '^3D body: ' validate.txt)" || fail "--validate printed no '3D body:' line"
[ "$line" = "3D body: $(summary_value out_free_0/summary.txt n_cells) cells, $(summary_value out_free_0/summary.txt n_dofs) DoFs (FESystem<3>[FE_Q<3>(1)^3-FE_DGP<3>(0)]), 1 MPI process(es)" ] ||
  fail "--validate says '$line', not the run's cells and DoFs"
pass "--validate: $line"
grep -q "^rollnip: 'free_0.prm' is valid" validate.txt || fail "--validate did not say free_0.prm is valid"
