#ifndef rollnip_geometry_roll_mesh_h
#define rollnip_geometry_roll_mesh_h

#include <deal.II/distributed/tria.h>

#include <rollnip/global.h>
#include <rollnip/parameters.h>

namespace rollnip
{
  /**
   * Builds the cover mesh into @p triangulation (empty on entry): either the
   * structured sector annulus, graded towards the nip at theta = 0, or the
   * gmsh file of Mesh/Mesh file. Boundary ids follow boundary_ids.h; both
   * arcs (and, for the built-in mesh, every cell) carry a polar manifold so
   * that refinement stays on the circles. Global refinements are applied.
   *
   * Throws a one-line message if the mesh file is missing or unreadable,
   * lacks one of the four boundary ids, or does not match Geometry.
   */
  void
  make_roll_mesh(const Parameters::AllParameters           &parameters,
                 parallel::distributed::Triangulation<dim> &triangulation);

  /// Sizes of n cells on an interval of length L whose widths grow
  /// geometrically by the total ratio (last / first) given.
  std::vector<double>
  graded_steps(const unsigned int n, const double length, const double ratio);
} // namespace rollnip

#endif
