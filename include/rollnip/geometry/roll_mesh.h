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

  /// Reads the gmsh mesh of @p parameters (Mesh/Source = gmsh) and checks
  /// it as make_roll_mesh() does, before any refinement, its messages naming
  /// the entries with @p prefix ("Mating roll/" for the mating roll);
  /// returns its number of coarse cells.
  unsigned int
  check_gmsh_mesh(const Parameters::AllParameters &parameters,
                  const std::string               &prefix);

  /// The gmsh mesh of @p parameters (Mesh/Source = gmsh) into the empty
  /// @p coarse, checked as make_roll_mesh() checks it, unrefined and
  /// without manifolds: the cross-section the 3D body extrudes.
  void
  read_gmsh_cross_section(const Parameters::AllParameters &parameters,
                          Triangulation<dim>              &coarse);

  /// Sizes of n cells on an interval of length L whose widths grow
  /// geometrically by the total ratio (last / first) given.
  std::vector<double>
  graded_steps(const unsigned int n, const double length, const double ratio);

  /// The coarse cell widths in theta [rad] of the builtin mesh:
  /// Mesh::circumferential_steps if a driver set them, else the graded
  /// cells of Mesh/Circumferential cells and grading.
  std::vector<double>
  coarse_circumferential_steps(const Parameters::AllParameters &parameters);

  /// The cells of @p steps re-cut to the total @p length so that the cells
  /// near the start (the nip) stay exactly as they are: cells are dropped
  /// from, or added at the growth rate of the last two to, the far end, and
  /// the last cell takes up the remainder (a remainder under half a cell
  /// widens the one before instead).
  std::vector<double>
  extend_steps(const std::vector<double> &steps, const double length);
} // namespace rollnip

#endif
