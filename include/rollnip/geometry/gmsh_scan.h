#ifndef rollnip_geometry_gmsh_scan_h
#define rollnip_geometry_gmsh_scan_h

#include <deal.II/base/exceptions.h>

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>

#include <istream>
#include <set>
#include <string>

namespace rollnip
{
  /**
   * The dimension of the mesh in the ASCII gmsh file @p file (format 2 or
   * 4): the largest dimension of its elements, 3 for a volume mesh, 2 for a
   * surface mesh (a cross-section). 0 when the file cannot be scanned
   * (missing, binary, or no $Elements section): GridIn then says what is
   * wrong. Lets Mesh/Source = gmsh choose between extruding a cross-section
   * and reading a 3D body, and refuse a 3D file in a 2D run by name.
   */
  unsigned int
  gmsh_mesh_dimension(const std::string &file);

  /// The gmsh element types (the numbers of the gmsh manual) in the ASCII
  /// gmsh file @p file; empty when it cannot be scanned.
  std::set<int>
  gmsh_element_types(const std::string &file);

  /// Whether every volume element of @p file is a hexahedron (8, 20 or
  /// 27 nodes); the 3D body refuses tetrahedra, prisms and pyramids by
  /// name before GridIn reads them.
  bool
  gmsh_volume_cells_are_hexahedra(const std::string &file);

  /// The gmsh mesh in @p in read into @p coarse; a file GridIn cannot
  /// read becomes the one-line error @p unreadable (GridIn's own message
  /// names neither the file nor the parameter).
  template <int dim>
  void
  read_gmsh_mesh(std::istream               &in,
                 dealii::Triangulation<dim> &coarse,
                 const std::string          &unreadable)
  {
    dealii::GridIn<dim> grid_in;
    grid_in.attach_triangulation(coarse);
    try
      {
        grid_in.read_msh(in);
      }
    catch (...)
      {
        AssertThrow(false, dealii::ExcMessage(unreadable));
      }
  }
} // namespace rollnip

#endif
