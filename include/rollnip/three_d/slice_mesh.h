#ifndef rollnip_three_d_slice_mesh_h
#define rollnip_three_d_slice_mesh_h

#include <deal.II/base/types.h>
#include <deal.II/distributed/tria.h>

#include <rollnip/parameters.h>

#include <cmath>
#include <vector>

namespace rollnip
{
  namespace three_d
  {
    /// The 3D body's dimension; hides rollnip::dim (= 2) in this namespace.
    constexpr unsigned int dim = 3;

    /// Boundary ids of the slice: those of boundary_ids.h for the
    /// cylindrical surfaces and the two edges, and the two face planes.
    namespace SliceIds
    {
      constexpr types::boundary_id inner_arc     = 0;
      constexpr types::boundary_id outer_arc     = 1;
      constexpr types::boundary_id symmetry_edge = 2;
      constexpr types::boundary_id far_edge      = 3;
      /// z = 0: the symmetry plane through the middle of the face.
      constexpr types::boundary_id near_face = 4;
      /// z = Slice thickness.
      constexpr types::boundary_id far_face = 5;
    } // namespace SliceIds

    /// The mean distance of @p cell's vertices from the roll axis [mm]: the
    /// middle radius of a cell between two arcs. The centre's distance is
    /// not: a cell wide in theta has its centre inside its inner arc.
    template <typename CellIterator>
    double
    mean_vertex_radius(const CellIterator &cell)
    {
      double sum = 0;
      for (const unsigned int v : cell->vertex_indices())
        sum += std::hypot(cell->vertex(v)[0], cell->vertex(v)[1]);
      return sum / cell->n_vertices();
    }

    /// Where along the axis the line load is given.
    struct AxialPlanes
    {
      /// [mm], from 0 to the body's length.
      std::vector<double> z;
      /// Whether every cell of the cover lies between two neighbouring
      /// planes (the extruded body, a drawn mesh in layers): then the
      /// planes are those of the nodes. Otherwise (a drawn mesh not in
      /// layers) they are stations that share each node's force by
      /// linear hat functions in z.
      bool layered = true;
    };

    /// The gmsh cross-section of Mesh/Mesh file (checked as in 2D: quads,
    /// ids 0..3 on the arcs and edges of Geometry) refined @p level times
    /// in its polar chart, so that a structured annulus halves in r and
    /// theta as the builtin mesh does, into the empty @p flat, flattened
    /// (level 0 only, no manifolds).
    void
    refined_gmsh_cross_section(const Parameters::AllParameters &parameters,
                               const unsigned int               level,
                               Triangulation<2>                &flat);

    /// The (r, theta, z) box @p body bent into Cartesian coordinates about
    /// the z axis.
    void
    bend_into_cylinder(Triangulation<dim> &body);

    /// Every step of @p steps cut into 2^@p level equal ones: the cells of
    /// the 2D mesh level @p level in a coarse mesh.
    std::vector<double>
    halved_steps(const std::vector<double> &steps, const unsigned int level);

    /**
     * The cross-section of Geometry and Mesh extruded along z over
     * @p thickness with @p layers cells, into @p triangulation: the builtin
     * sector annulus (the same radial and graded circumferential cells as
     * the 2D fixed mesh) or, with Mesh/Source = gmsh, the quadrilateral
     * cross-section of Mesh/Mesh file (checked as in 2D). The
     * 2D mesh level @p level is built into the coarse mesh by halving
     * every in-plane cell @p level times (in r and theta, as the polar
     * manifold refines the 2D mesh; a gmsh mesh in its polar chart), so
     * that the slice stays @p layers cells thick and its vertices are the
     * builtin 2D mesh's at that level. The
     * layers thin towards z = @p thickness by @p axial_grading
     * (axial_grading.h). All
     * cells carry a cylindrical manifold about the roll axis (the z axis)
     * and, as material id, the cover layer they lie in (0 on the core,
     * geometry/cover_layers.h).
     *
     * A Mesh/Mesh file holding a 3D mesh is the body as drawn
     * (drawn_mesh.h): its own layers replace @p layers and
     * @p axial_grading, and it is refined @p level times in all three
     * directions. Returns the z of the planes between the layers of cells
     * [mm], 0 to @p thickness (a drawn mesh not in layers: its stations).
     */
    AxialPlanes
    make_slice_mesh(const Parameters::AllParameters           &parameters,
                    const unsigned int                         level,
                    const double                               thickness,
                    const unsigned int                         layers,
                    parallel::distributed::Triangulation<dim> &triangulation,
                    const double axial_grading = 1.);
  } // namespace three_d
} // namespace rollnip

#endif
