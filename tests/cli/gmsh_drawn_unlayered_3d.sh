#!/usr/bin/env bash
# A cover drawn in 3D whose cells are not in layers along the axis
# (meshes/quarter_roll_tet_split_3d.geo: tetrahedra split into hexahedra by
# gmsh). rollnip gives its line load along the axis at stations, each
# active node's force shared by the stations' hat functions in z.
#
# Usage: bash gmsh_drawn_unlayered_3d.sh ROLLNIP GMSH MPIEXEC SCENE SPLIT_GEO
#          LAYERED_GEO
#   SCENE        parameters/slice_3d.prm (u0 = 0.5, 1, 2 mm; fixed axial
#                far face: plane strain)
#   SPLIT_GEO    meshes/quarter_roll_tet_split_3d.geo
#   LAYERED_GEO  meshes/quarter_roll_free_3d.geo (the same cover in layers)
#
# 1. Plane strain on a 10 mm slice, levels 0 and 1: P(u0) within 0.5 % of
#    the 2D P(u0) of the scene (2D Q2-P1 at level 3 on the nip-fitted mesh:
#    2.2103521, 6.3289393, 20.026731 N/mm) at level 1 (measured: 0.18 %,
#    0.07 %, 0.03 %), closer than at level 0 at every u0; the line load at
#    every station within 0.3 % of P at level 1 (the exact solution does
#    not vary along the axis; measured: 0.15 %); and the
#    stations' loads times their widths (half the gaps on either side) sum
#    to P times the length to 1e-6 at both levels (the hats share every
#    node's force without loss).
# 2. A free cover end, 20 mm, u0 = 1 mm, level 1: P within 0.5 % of the
#    same cover drawn in layers (quarter_roll_free_3d.geo, level 1; the two
#    differ by their discretisation errors, 0.06 % measured), and the line
#    load at the end below 0.6 times the middle's (0.37 measured).
# 3. The free end at level 0 on 2 MPI processes: P and the line load at
#    every station as on 1 to 1e-8 (each process integrates its own faces
#    against the hats; the sums meet).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 6 ] ||
  fail "usage: gmsh_drawn_unlayered_3d.sh ROLLNIP GMSH MPIEXEC SCENE SPLIT_GEO LAYERED_GEO"
rollnip="$(realpath "$1")"
gmsh="$2"
mpiexec="$3"
scene="$(realpath "$4")"
split_geo="$(realpath "$5")"
layered_geo="$(realpath "$6")"
require_executable rollnip "$rollnip"
require_executable "gmsh (needed to mesh the cover)" "$gmsh"
require_executable "mpiexec (MPIEXEC_EXECUTABLE)" "$mpiexec"
start_test gmsh_drawn_unlayered_3d
mpi_setup "$mpiexec"

gmsh_mesh "$gmsh" 3 "$split_geo" split_10.msh -setnumber SliceThickness 10
gmsh_mesh "$gmsh" 3 "$split_geo" split_20.msh -setnumber SliceThickness 20
gmsh_mesh "$gmsh" 3 "$layered_geo" layered_20.msh -setnumber SliceThickness 20 \
  -setnumber NLayers 2

# run NAME LEVEL MESH_FILE LENGTH [free]: SCENE on MESH_FILE at LEVEL, the
# slice LENGTH mm long; with "free" a free cover end at u0 = 1 mm.
run()
{
  cp "$scene" "$1.prm"
  {
    printf '\nsubsection Mesh\n  set Global refinements = %s\n' "$2"
    printf '  set Source = gmsh\n  set Mesh file = %s\nend\n' "$3"
    printf 'subsection Three d\n  set Slice thickness = %s\n' "$4"
    if [ $# -eq 5 ]; then
      printf '  set Far face = free\nend\nsubsection Contact\n  set Values = 1\n'
    fi
    printf 'end\n'
    quiet_output "out_$1"
  } >> "$1.prm"
  run_named "$1"
}

# conserved NAME LENGTH: sum of q_j w_j over the stations against P L.
conserved()
{
  local total
  total="$(awk -F, 'BEGIN { n = 0 } NR > 1 { z[n] = $1; q[n] = $2; n++ }
    END { for (j = 0; j < n; j++) {
            w = 0
            if (j > 0) w += (z[j] - z[j - 1]) / 2
            if (j < n - 1) w += (z[j + 1] - z[j]) / 2
            s += q[j] * w }
          printf "%.12g", s }' "out_$1/line_load_along_axis.csv")"
  check_rel_close "$1: sum of the stations' q w against P L" "$total" \
    "$(awk -v p="$(summary_value "out_$1/summary.txt" nip_load_P_N_per_mm)" \
      -v l="$2" 'BEGIN { printf "%.12g", p * l }')" 1e-6
}

P_2d=(2.2103521 6.3289393 20.026731)
for level in 0 1; do
  run slice_$level $level split_10.msh 10
  conserved slice_$level 10
done
for k in 1 2 3; do
  P0="$(csv_value out_slice_0/slice_3d.csv P_N_per_mm $k)"
  P1="$(csv_value out_slice_1/slice_3d.csv P_N_per_mm $k)"
  u0="$(csv_value out_slice_1/slice_3d.csv u0_mm $k)"
  reference="${P_2d[$((k - 1))]}"
  check_rel_close "unlayered slice, level 1, P(u0 = $u0 mm) against 2D" \
    "$P1" "$reference" 5e-3
  e0="$(awk -v p="$P0" -v r="$reference" 'BEGIN { d = p / r - 1; print (d < 0 ? -d : d) }')"
  e1="$(awk -v p="$P1" -v r="$reference" 'BEGIN { d = p / r - 1; print (d < 0 ? -d : d) }')"
  check_less "unlayered slice, u0 = $u0 mm: |error| at level 1 (level 0: $e0)" "$e1" "$e0"
done
P="$(summary_value out_slice_1/summary.txt nip_load_P_N_per_mm)"
stations="$(($(wc -l < out_slice_1/line_load_along_axis.csv) - 1))"
[ "$stations" -ge 3 ] || fail "the level-1 slice has $stations stations, expected 3 or more"
for j in $(seq 1 "$stations"); do
  check_rel_close "unlayered slice, level 1, station $j: q against P" \
    "$(csv_value out_slice_1/line_load_along_axis.csv line_load_N_per_mm "$j")" \
    "$P" 3e-3
done

run end_split 1 split_20.msh 20 free
run end_layered 1 layered_20.msh 20 free
conserved end_split 20
check_rel_close "free end, unlayered against layered: P" \
  "$(summary_value out_end_split/summary.txt nip_load_P_N_per_mm)" \
  "$(summary_value out_end_layered/summary.txt nip_load_P_N_per_mm)" 5e-3
rows="$(($(wc -l < out_end_split/line_load_along_axis.csv) - 1))"
q_middle="$(csv_value out_end_split/line_load_along_axis.csv line_load_N_per_mm 1)"
q_end="$(csv_value out_end_split/line_load_along_axis.csv line_load_N_per_mm "$rows")"
check_less "free end, unlayered: q at the end over q at the middle" \
  "$(awk -v a="$q_end" -v b="$q_middle" 'BEGIN { print a / b }')" 0.6

run end_serial 0 split_20.msh 20 free
cp end_serial.prm end_mpi.prm
quiet_output out_end_mpi >> end_mpi.prm
rc=0
timeout --kill-after=10 300 "$mpiexec" "${mpi_flags[@]}" -np 2 "$rollnip" \
  end_mpi.prm > end_mpi.txt 2>&1 || rc=$?
[ "$rc" -eq 0 ] || { cat end_mpi.txt; fail "the run on 2 MPI processes failed (exit code $rc)"; }
[ "$(summary_value out_end_mpi/summary.txt mpi_processes)" -eq 2 ] ||
  fail "the MPI run does not report mpi_processes = 2"
check_rel_close "free end, 2 processes against 1: P" \
  "$(summary_value out_end_mpi/summary.txt nip_load_P_N_per_mm)" \
  "$(summary_value out_end_serial/summary.txt nip_load_P_N_per_mm)" 1e-8
rows="$(wc -l < out_end_serial/line_load_along_axis.csv)"
[ "$rows" -eq "$(wc -l < out_end_mpi/line_load_along_axis.csv)" ] ||
  fail "2 processes give other stations than 1"
for k in $(seq 1 $((rows - 1))); do
  check_rel_close "free end, 2 processes against 1, station $k: q" \
    "$(csv_value out_end_mpi/line_load_along_axis.csv line_load_N_per_mm "$k")" \
    "$(csv_value out_end_serial/line_load_along_axis.csv line_load_N_per_mm "$k")" 1e-8
done
