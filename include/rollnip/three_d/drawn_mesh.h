#ifndef rollnip_three_d_drawn_mesh_h
#define rollnip_three_d_drawn_mesh_h

#include <deal.II/grid/tria.h>

#include <rollnip/parameters.h>
#include <rollnip/three_d/slice_mesh.h>

#include <string>
#include <vector>

namespace rollnip
{
  namespace three_d
  {
    /**
     * The 3D hexahedral gmsh mesh of Mesh/Mesh file (a body drawn in 3D,
     * doc/three_d.md "A gmsh mesh drawn in 3D") into the empty @p coarse,
     * unrefined and without manifolds. Refused, in one line naming the
     * file, unless: every cell is a hexahedron with positive volume; the
     * mesh spans z = 0 to @p length (Three d/Slice thickness); every
     * boundary face carries one of the ids of SliceIds and lies where that
     * id says (the arcs r = R1, R0 of Geometry, the planes theta = 0 and
     * theta = sector angle, z = 0 and z = @p length); and no cell
     * straddles an interface of a layered cover. Returns the planes of
     * the mesh's layers along the axis (gmsh's Extrude with Layers), or,
     * when its cells are not in layers, equidistant stations twice as far
     * apart as the outer surface's faces are long in z (their median).
     */
    AxialPlanes
    read_drawn_slice(const Parameters::AllParameters &parameters,
                     const double                     length,
                     Triangulation<3>                &coarse);

    /// Whether Mesh/Mesh file is a 3D mesh the 3D body reads as drawn
    /// (Mesh/Source = gmsh and a volume mesh in the file).
    bool
    is_drawn_slice(const Parameters::AllParameters &parameters);
  } // namespace three_d
} // namespace rollnip

#endif
