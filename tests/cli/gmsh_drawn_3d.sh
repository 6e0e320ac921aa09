#!/usr/bin/env bash
# The 3D body on a mesh drawn in 3D (Mesh/Mesh file holds a hexahedral
# volume mesh) against the same body extruded from its 2D cross-section.
#
# Usage: bash gmsh_drawn_3d.sh ROLLNIP GMSH MPIEXEC SCENE FREE_GEO FREE_3D_GEO
#   SCENE        parameters/slice_3d.prm (the plane-strain slice)
#   FREE_GEO     meshes/quarter_roll_free.geo (the 2D cross-section)
#   FREE_3D_GEO  meshes/quarter_roll_free_3d.geo (that cross-section
#                extruded by gmsh into hexahedra)
#
# quarter_roll_free_3d.geo with NLayers n is, up to the numbering of nodes
# and cells and to gmsh's round-off in the node coordinates (2e-8 mm), the
# extrusion rollnip makes of quarter_roll_free.geo's mesh with Layers = 2n:
# the same cross-section (the same points, sizes and final split), cut by
# gmsh's split into 2n equal layers. So both must give the same answer to
# round-off (1e-8 relative): P, b and the active nodes of the plane-strain
# slice at u0 = 0.5, 1, 2 mm, and on a free cover end (Far face = free,
# 20 mm, u0 = 1 mm) the line load at every plane along the axis, its decay
# length, the end-face bulge and the bond stresses. At mesh level 1 the
# drawn mesh is refined in 3D on the cylindrical manifold (r, theta and z
# halved), the extruded one in the polar chart with twice the layers: the
# same mesh again. The drawn free end on 2 MPI processes must repeat the
# serial run to 1e-8, and the slice with Q2-P1 the extruded one. A drawn
# run warns that Three d/Layers is ignored.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 6 ] ||
  fail "usage: gmsh_drawn_3d.sh ROLLNIP GMSH MPIEXEC SCENE FREE_GEO FREE_3D_GEO"
rollnip="$(realpath "$1")"
gmsh="$2"
mpiexec="$3"
scene="$(realpath "$4")"
free_geo="$(realpath "$5")"
free_3d_geo="$(realpath "$6")"
require_executable rollnip "$rollnip"
require_executable "gmsh (needed to mesh the cover)" "$gmsh"
require_executable "mpiexec (MPIEXEC_EXECUTABLE)" "$mpiexec"
start_test gmsh_drawn_3d
mpi_setup "$mpiexec"

gmsh_mesh "$gmsh" 2 "$free_geo" section.msh
gmsh_mesh "$gmsh" 3 "$free_3d_geo" drawn_1.msh -setnumber SliceThickness 1 -setnumber NLayers 1
gmsh_mesh "$gmsh" 3 "$free_3d_geo" drawn_20.msh -setnumber SliceThickness 20 -setnumber NLayers 2

# write NAME LEVEL MESH_FILE LAYERS [LENGTH]: SCENE on MESH_FILE at LEVEL;
# with LENGTH a free cover end of that length at u0 = 1 mm.
write()
{
  cp "$scene" "$1.prm"
  {
    printf '\nsubsection Mesh\n  set Global refinements = %s\n' "$2"
    printf '  set Source = gmsh\n  set Mesh file = %s\nend\n' "$3"
    printf 'subsection Three d\n  set Layers = %s\n' "$4"
    if [ $# -eq 5 ]; then
      printf '  set Slice thickness = %s\n  set Far face = free\n' "$5"
      printf 'end\nsubsection Contact\n  set Values = 1\n'
    fi
    printf 'end\n'
    quiet_output "out_$1"
  } >> "$1.prm"
}
run() { write "$@"; run_named "$1"; }

# agree NAME_A NAME_B LABEL: the headline numbers of the two runs to 1e-8.
agree()
{
  local a="out_$1" b="out_$2" label="$3" k column key
  for k in $(seq 1 "$(($(wc -l < "$a/slice_3d.csv") - 1))"); do
    for column in P_N_per_mm half_chord_b_mm active_nodes; do
      check_rel_close "$label, u0 row $k: $column" \
        "$(csv_value "$b/slice_3d.csv" $column $k)" \
        "$(csv_value "$a/slice_3d.csv" $column $k)" 1e-8
    done
  done
  local rows
  rows="$(wc -l < "$a/line_load_along_axis.csv")"
  [ "$rows" -eq "$(wc -l < "$b/line_load_along_axis.csv")" ] ||
    fail "$label: the line loads along the axis have different planes"
  for k in $(seq 1 $((rows - 1))); do
    check_close "$label, plane $k: z_mm" \
      "$(csv_value "$b/line_load_along_axis.csv" z_mm $k)" \
      "$(csv_value "$a/line_load_along_axis.csv" z_mm $k)" 1e-7
    check_rel_close "$label, plane $k: line_load_N_per_mm" \
      "$(csv_value "$b/line_load_along_axis.csv" line_load_N_per_mm $k)" \
      "$(csv_value "$a/line_load_along_axis.csv" line_load_N_per_mm $k)" 1e-8
  done
  shift 3
  for key in "$@"; do
    check_rel_close "$label: $key" "$(summary_value "$b/summary.txt" "$key")" \
      "$(summary_value "$a/summary.txt" "$key")" 1e-8
  done
}

run slice_extruded 0 section.msh 2
run slice_drawn 0 drawn_1.msh 2
agree slice_extruded slice_drawn "slice, drawn against extruded" n_cells n_dofs
# Layers = 2 means nothing to a drawn mesh: said once, in a warning.
warning="Three d/Layers and Three d/Axial grading are ignored"
[ "$(grep -c "^rollnip: warning: $warning.*drawn_1.msh" slice_drawn.err)" -eq 1 ] ||
  fail "the drawn run does not warn once that Three d/Layers is ignored"
! grep -q "$warning" slice_extruded.err ||
  fail "the extruded run warns that Three d/Layers is ignored"
pass "the drawn run (only) warns that Three d/Layers is ignored"

# Q2-P1 (MappingQ(2) on the cylindrical manifold, the mid-layer planes of
# the line load) at u0 = 1 mm.
for kind in extruded drawn; do
  mesh_file=section.msh
  [ $kind = drawn ] && mesh_file=drawn_1.msh
  write slice_q2_$kind 0 $mesh_file 2
  printf 'subsection Discretization\n  set Element = Q2-P1\nend\n' >> slice_q2_$kind.prm
  printf 'subsection Contact\n  set Values = 1\nend\n' >> slice_q2_$kind.prm
  run_named slice_q2_$kind
done
agree slice_q2_extruded slice_q2_drawn "slice, Q2-P1, drawn against extruded" \
  n_dofs

free_end_keys=(n_cells n_dofs end_deficit_length_l_mm end_bulge_uz_mm
  bond_shear_peak_MPa bond_corner_sigma_rr_mean_h_MPa
  bond_tension_peak_sigma_rr_MPa)
for level in 0 1; do
  run end_extruded_$level $level section.msh $((4 << level)) 20
  run end_drawn_$level $level drawn_20.msh 4 20
  agree end_extruded_$level end_drawn_$level \
    "free end, level $level, drawn against extruded" "${free_end_keys[@]}"
done

write end_drawn_mpi 0 drawn_20.msh 4 20
rc=0
timeout --kill-after=10 300 "$mpiexec" "${mpi_flags[@]}" -np 2 "$rollnip" \
  end_drawn_mpi.prm > end_drawn_mpi.txt 2>&1 || rc=$?
[ "$rc" -eq 0 ] || { cat end_drawn_mpi.txt; fail "the run on 2 MPI processes failed (exit code $rc)"; }
[ "$(summary_value out_end_drawn_mpi/summary.txt mpi_processes)" -eq 2 ] ||
  fail "the MPI run does not report mpi_processes = 2"
agree end_drawn_0 end_drawn_mpi "free end, drawn, 2 processes against 1" \
  "${free_end_keys[@]}"
echo "drawn free end, level 0: P = $(summary_value out_end_drawn_0/summary.txt nip_load_P_N_per_mm) N/mm"
