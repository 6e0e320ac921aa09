#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <rollnip/boundary_ids.h>
#include <rollnip/cost_estimate.h>
#include <rollnip/geometry/cover_layers.h>
#include <rollnip/geometry/gmsh_scan.h>
#include <rollnip/geometry/roll_mesh.h>

#include <cmath>
#include <fstream>
#include <set>

namespace rollnip
{
  std::vector<double>
  graded_steps(const unsigned int n, const double length, const double ratio)
  {
    // Widths w_k = w_0 g^k with g^(n-1) = ratio, scaled to sum to length.
    const double        g = (n > 1) ? std::pow(ratio, 1. / (n - 1)) : 1.;
    std::vector<double> steps(n);
    double              sum = 0;
    for (unsigned int k = 0; k < n; ++k)
      sum += (steps[k] = std::pow(g, k));
    for (double &s : steps)
      s *= length / sum;
    return steps;
  }

  std::vector<double>
  coarse_circumferential_steps(const Parameters::AllParameters &parameters)
  {
    const auto &m = parameters.mesh;
    if (!m.circumferential_steps.empty())
      return m.circumferential_steps;
    return graded_steps(m.circumferential_cells,
                        parameters.geometry.sector_angle,
                        m.circumferential_grading);
  }

  std::vector<double>
  extend_steps(const std::vector<double> &steps, const double length)
  {
    Assert(!steps.empty() && length > 0, ExcInternalError());
    const double growth =
      steps.size() > 1 ? steps[steps.size() - 1] / steps[steps.size() - 2] : 1.;
    std::vector<double> result;
    double              sum = 0, next = steps[0];
    for (std::size_t k = 0;; ++k)
      {
        next = k < steps.size() ? steps[k] : next * growth;
        if (sum + next > length * (1 + 1e-12))
          break;
        result.push_back(next);
        sum += next;
      }
    const double rest = length - sum;
    if (rest > 0.5 * next || result.empty())
      result.push_back(rest);
    else
      result.back() += rest;
    return result;
  }

  namespace
  {
    /// The sector annulus: a graded rectangle in (r, theta), mapped to
    /// Cartesian coordinates. Left/right/bottom/top of the rectangle
    /// (colorize ids 0..3) are exactly r = R1, r = R0, theta = 0 and
    /// theta = sector angle, i.e. the ids of boundary_ids.h.
    void
    make_builtin(const Parameters::AllParameters &parameters,
                 Triangulation<dim>              &coarse)
    {
      const auto                            &g     = parameters.geometry;
      const auto                            &m     = parameters.mesh;
      const std::vector<std::vector<double>> steps = {
        radial_steps(parameters, m.radial_grading),
        coarse_circumferential_steps(parameters)};
      GridGenerator::subdivided_hyper_rectangle(coarse,
                                                steps,
                                                Point<dim>(g.inner_radius, 0.),
                                                Point<dim>(g.outer_radius,
                                                           g.sector_angle),
                                                /*colorize=*/true);
      static_assert(BoundaryIds::inner_arc == 0 &&
                      BoundaryIds::outer_arc == 1 &&
                      BoundaryIds::symmetry_edge == 2 &&
                      BoundaryIds::far_edge == 3,
                    "colorize numbering must match boundary_ids.h");
      GridTools::transform(
        [](const Point<dim> &p) {
          return Point<dim>(p[0] * std::cos(p[1]), p[0] * std::sin(p[1]));
        },
        coarse);
      coarse.set_all_manifold_ids(ManifoldIds::polar);
      set_layer_ids(parameters, coarse);
    }

    void
    make_from_gmsh(const Parameters::AllParameters &parameters,
                   Triangulation<dim>              &coarse,
                   const std::string               &prefix)
    {
      const std::string &file = parameters.mesh.mesh_file;
      std::ifstream      in(file);
      AssertThrow(in.good(),
                  ExcMessage(prefix + "Mesh/Mesh file: cannot open '" + file +
                             "'"));
      AssertThrow(gmsh_mesh_dimension(file) != 3,
                  ExcMessage(prefix + "Mesh/Mesh file: '" + file +
                             "' holds a 3D mesh; a 2D run needs a "
                             "quadrilateral cross-section (Three d/Enabled = "
                             "true reads a 3D hexahedral mesh as drawn)"));
      read_gmsh_mesh(in,
                     coarse,
                     prefix + "Mesh/Mesh file: '" + file +
                       "' is not a readable gmsh quadrilateral mesh");
      // Q1-P0 and the polar manifold need quadrilaterals; a triangle (or
      // mixed) mesh would crash the first face loop.
      AssertThrow(coarse.n_active_cells() > 0 &&
                    coarse.all_reference_cells_are_hyper_cube(),
                  ExcMessage(prefix + "Mesh/Mesh file: '" + file +
                             "' contains triangles (or no cells); rollnip "
                             "needs a quadrilateral mesh (in gmsh: Recombine "
                             "Surface, or Mesh.RecombineAll = 1)"));
      // Arcs follow the circles under refinement; the interior stays flat.
      for (const auto &cell : coarse.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() &&
              (face->boundary_id() == BoundaryIds::inner_arc ||
               face->boundary_id() == BoundaryIds::outer_arc))
            face->set_manifold_id(ManifoldIds::polar);
    }

    /// Distance [mm] of @p x from the ray from the origin at angle @p a
    /// (to the origin itself behind it).
    double
    distance_from_ray(const Point<dim> &x, const double a)
    {
      const Tensor<1, dim> d({std::cos(a), std::sin(a)});
      const double         along = x * d;
      return along >= 0 ? std::abs(x[0] * d[1] - x[1] * d[0]) : x.norm();
    }

    /// The mesh must carry exactly the ids 0..3, its arcs must lie on the
    /// circles of Geometry and its edges on the rays theta = 0 and the
    /// sector angle, so that every condition acts where it says.
    void
    check_mesh(const Parameters::AllParameters &parameters,
               const Triangulation<dim>        &coarse,
               const std::string               &origin,
               const std::string               &prefix)
    {
      std::set<types::boundary_id> found;
      const double                 R[2]  = {parameters.geometry.inner_radius,
                                            parameters.geometry.outer_radius};
      double                       worst = 0;
      // Largest distance of the symmetry edge (id 2) from the ray
      // theta = 0 and of the far edge (id 3) from theta = sector angle.
      double       edge_distance[2] = {0, 0};
      const double sector           = parameters.geometry.sector_angle;
      for (const auto &cell : coarse.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const types::boundary_id b = face->boundary_id();
              AssertThrow(b < BoundaryIds::n_boundaries,
                          ExcMessage(origin + ": boundary id " +
                                     std::to_string(b) +
                                     " is not one of 0 (inner arc), 1 (outer "
                                     "arc), 2 (symmetry edge), 3 (far edge)"));
              found.insert(b);
              if (b == BoundaryIds::inner_arc || b == BoundaryIds::outer_arc)
                for (unsigned int v = 0; v < 2; ++v)
                  worst =
                    std::max(worst,
                             std::abs(face->vertex(v).norm() - R[b]) / R[b]);
              else
                for (unsigned int v = 0; v < 2; ++v)
                  edge_distance[b - BoundaryIds::symmetry_edge] =
                    std::max(edge_distance[b - BoundaryIds::symmetry_edge],
                             distance_from_ray(face->vertex(v),
                                               b == BoundaryIds::symmetry_edge
                                                 ? 0.
                                                 : sector) /
                               R[1]);
            }
      for (types::boundary_id b = 0; b < BoundaryIds::n_boundaries; ++b)
        AssertThrow(found.count(b),
                    ExcMessage(origin + ": the mesh has no boundary with id " +
                               std::to_string(b) +
                               " (0 inner arc, 1 outer arc, 2 symmetry edge, "
                               "3 far edge)"));
      AssertThrow(worst < 1e-6,
                  ExcMessage(origin +
                             ": the arcs with ids 0 and 1 do not lie on " +
                             prefix +
                             "Geometry/Inner radius and Outer radius (relative "
                             "mismatch " +
                             std::to_string(worst) + ")"));
      const std::string edge_names[2] = {"symmetry edge (id 2) does not lie "
                                         "on the ray theta = 0",
                                         "far edge (id 3) does not lie on the "
                                         "ray theta = " +
                                           prefix + "Geometry/Sector angle (" +
                                           std::to_string(sector * 180. /
                                                          numbers::PI) +
                                           " deg)"};
      for (unsigned int e = 0; e < 2; ++e)
        AssertThrow(edge_distance[e] < 1e-6,
                    ExcMessage(origin + ": the " + edge_names[e] +
                               " (relative distance " +
                               std::to_string(edge_distance[e]) +
                               "); are the ids swapped, or is the mesh drawn "
                               "for another sector?"));
    }
  } // namespace

  namespace
  {
    /// The gmsh mesh of @p parameters into @p coarse, checked against
    /// Geometry and the layers, its messages naming the entries with
    /// @p prefix.
    void
    read_checked_gmsh(const Parameters::AllParameters &parameters,
                      const std::string               &prefix,
                      Triangulation<dim>              &coarse)
    {
      make_from_gmsh(parameters, coarse, prefix);
      const std::string origin =
        prefix + "Mesh/Mesh file '" + parameters.mesh.mesh_file + "'";
      check_mesh(parameters, coarse, origin, prefix);
      check_layer_ids(parameters, coarse, origin, prefix);
    }
  } // namespace

  unsigned int
  check_gmsh_mesh(const Parameters::AllParameters &parameters,
                  const std::string               &prefix)
  {
    Triangulation<dim> coarse;
    read_checked_gmsh(parameters, prefix, coarse);
    return coarse.n_active_cells();
  }

  void
  read_gmsh_cross_section(const Parameters::AllParameters &parameters,
                          Triangulation<dim>              &coarse)
  {
    read_checked_gmsh(parameters, "", coarse);
    coarse.reset_all_manifolds();
    coarse.set_all_manifold_ids(numbers::flat_manifold_id);
  }

  void
  make_roll_mesh(const Parameters::AllParameters           &parameters,
                 parallel::distributed::Triangulation<dim> &triangulation)
  {
    Triangulation<dim> coarse;
    if (parameters.mesh.source == Parameters::MeshSource::gmsh)
      read_checked_gmsh(parameters, "", coarse);
    else
      {
        make_builtin(parameters, coarse);
        check_mesh(parameters, coarse, "built-in mesh", "");
      }
    check_cost(parameters, coarse.n_active_cells());
    triangulation.copy_triangulation(coarse);
    triangulation.set_manifold(ManifoldIds::polar,
                               PolarManifold<dim>(Point<dim>()));
    triangulation.refine_global(parameters.mesh.global_refinements);
  }
} // namespace rollnip
