#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <rollnip/geometry/cover_layers.h>
#include <rollnip/geometry/roll_mesh.h>
#include <rollnip/material/law_factory.h>
#include <rollnip/parameter_entries.h>
#include <rollnip/three_d/axial_grading.h>
#include <rollnip/three_d/core_deflection.h>
#include <rollnip/three_d/core_tube.h>
#include <rollnip/three_d/slice_body.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

namespace rollnip
{
  namespace three_d
  {
    namespace
    {
      /// The boundary id of a face of the (r, theta, z) box with the
      /// centre @p c, before the box is bent into the tube.
      types::boundary_id
      tube_boundary_id(const Point<dim>                &c,
                       const Parameters::AllParameters &parameters,
                       const Parameters::ThreeD        &three_d)
      {
        const auto  &g   = parameters.geometry;
        const double tol = 1e-9 * (g.outer_radius + three_d.bearing_distance);
        const auto   at  = [tol](const double a, const double b) {
          return std::abs(a - b) < tol;
        };
        if (at(c[2], 0.))
          return SliceIds::near_face;
        if (at(c[2], three_d.bearing_distance))
          return CoreIds::journal;
        if (at(c[2], three_d.slice_thickness))
          return SliceIds::far_face; // the cover's end: the core goes on
        if (at(c[1], 0.))
          return SliceIds::symmetry_edge;
        if (at(c[1], g.sector_angle))
          return SliceIds::far_edge;
        if (at(c[0], three_d.core_inner_radius))
          return CoreIds::bore;
        if (at(c[0], g.outer_radius))
          return SliceIds::outer_arc;
        return CoreIds::bare_core;
      }
    } // namespace

    void
    check_elastic_core(const Parameters::AllParameters &parameters,
                       const Parameters::ThreeD        &three_d)
    {
      AssertThrow(parameters.mesh.source == Parameters::MeshSource::builtin,
                  ExcMessage("Three d/Core = elastic needs Mesh/Source = "
                             "builtin (the tube is meshed with the builtin "
                             "cross-section, not with a gmsh one)"));
      const double R1 = parameters.geometry.inner_radius;
      AssertThrow(three_d.core_inner_radius > 0 &&
                    three_d.core_inner_radius < R1,
                  ExcMessage("Three d/Core inner radius must lie between 0 "
                             "and Geometry/Inner radius (" +
                             Parameters::number(R1) + " mm), got " +
                             Parameters::number(three_d.core_inner_radius) +
                             " mm"));
      AssertThrow(three_d.bearing_distance > three_d.slice_thickness,
                  ExcMessage(
                    "Three d/Bearing distance must exceed Slice "
                    "thickness (" +
                    Parameters::number(three_d.slice_thickness) + " mm), got " +
                    Parameters::number(three_d.bearing_distance) + " mm"));
      AssertThrow(three_d.core_youngs_modulus > 0,
                  ExcMessage("Three d/Core Young's modulus must be positive"));
      using BC = Parameters::BoundaryCondition;
      AssertThrow(
        std::abs(parameters.geometry.sector_angle - numbers::PI) < 1e-12 &&
          parameters.boundary_conditions.condition[SliceIds::far_edge] ==
            BC::symmetry,
        ExcMessage("Three d/Core = elastic needs Geometry/Sector "
                   "angle = 180 and Boundary conditions/Far edge "
                   "= symmetry (the half tube bends as the whole)"));
      AssertThrow(CoreDeflection(three_d.core_deflection).is_zero(),
                  ExcMessage("Three d/Core deflection must be 0 with Core = "
                             "elastic (the core then bends by itself)"));
    }

    void
    make_core_tube_mesh(const Parameters::AllParameters           &parameters,
                        const Parameters::ThreeD                  &three_d,
                        const unsigned int                         level,
                        parallel::distributed::Triangulation<dim> &tria)
    {
      const auto  &g   = parameters.geometry;
      const double L   = three_d.slice_thickness;
      const double Lb  = three_d.bearing_distance;
      const double Ri  = three_d.core_inner_radius;
      auto         rad = std::vector<double>(2, (g.inner_radius - Ri) / 2.);
      const auto   cover =
        radial_steps(parameters, parameters.mesh.radial_grading);
      rad.insert(rad.end(), cover.begin(), cover.end());
      auto axial = axial_steps(L, three_d.layers, three_d.axial_grading);
      const unsigned int n_over =
        std::max<long>(1, std::lround((Lb - L) * three_d.layers / L));
      axial.insert(axial.end(), n_over, (Lb - L) / n_over);
      Triangulation<dim> box, tube;
      GridGenerator::subdivided_hyper_rectangle(
        box,
        {halved_steps(rad, level),
         halved_steps(coarse_circumferential_steps(parameters), level),
         axial},
        Point<dim>(Ri, 0., 0.),
        Point<dim>(g.outer_radius, g.sector_angle, Lb));
      const std::vector<double> radii = layer_radii(parameters);
      std::set<Triangulation<dim>::active_cell_iterator> beyond_face;
      for (const auto &cell : box.active_cell_iterators())
        {
          const Point<dim> c = cell->center();
          if (c[0] > g.inner_radius && c[2] > L)
            beyond_face.insert(cell);
          cell->set_material_id(c[0] < g.inner_radius
                                  ? parameters.material.n_layers()
                                  : layer_at_radius(radii, c[0]));
        }
      GridGenerator::create_triangulation_with_removed_cells(box,
                                                             beyond_face,
                                                             tube);
      for (const auto &face : tube.active_face_iterators())
        if (face->at_boundary())
          face->set_boundary_id(
            tube_boundary_id(face->center(), parameters, three_d));
      GridTools::transform(
        [](const Point<dim> &p) {
          return Point<dim>(p[0] * std::cos(p[1]), p[0] * std::sin(p[1]), p[2]);
        },
        tube);
      tube.set_all_manifold_ids(0);
      tria.copy_triangulation(tube);
      Tensor<1, dim> axis;
      axis[2] = 1.;
      tria.set_manifold(0, CylindricalManifold<dim>(axis, Point<dim>()));
    }

    std::unique_ptr<MaterialLaw<dim>>
    make_core_law(const Parameters::ThreeD &three_d)
    {
      const double         E  = three_d.core_youngs_modulus;
      const double         nu = three_d.core_poisson_ratio;
      Parameters::Material steel;
      steel.layer_C1            = {E / (4. * (1. + nu))}; // G / 2
      steel.layer_C2            = {0.};
      steel.layer_poisson_ratio = {nu};
      steel.theory              = Parameters::Theory::nonlinear;
      return make_layer_law<dim>(steel, 0);
    }

    std::vector<std::pair<double, double>>
    core_deflection_profile(const SliceBody &body)
    {
      const auto &dofs     = body.get_dof_handler();
      const auto &solution = body.current_solution();
      const auto  owned    = dofs.locally_owned_dofs();
      std::map<types::global_dof_index, std::array<double, 3>> local;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() == CoreIds::bore)
              for (unsigned int v = 0; v < face->n_vertices(); ++v)
                {
                  const auto dof = face->vertex_dof_index(v, 0);
                  if (owned.is_element(dof))
                    {
                      const Point<dim> X = face->vertex(v);
                      local[dof]         = {
                                {X[2], std::atan2(X[1], X[0]), solution[dof]}};
                    }
                }
      std::vector<std::array<double, 3>> mine, nodes;
      for (const auto &entry : local)
        mine.push_back(entry.second);
      for (const auto &part :
           Utilities::MPI::all_gather(body.mpi_communicator(), mine))
        nodes.insert(nodes.end(), part.begin(), part.end());
      std::sort(nodes.begin(), nodes.end());
      // One plane of nodes after the other, each sorted by theta.
      std::vector<std::pair<double, double>> profile;
      const double tol = 1e-9 * std::max(1., std::abs(nodes.back()[0]));
      for (std::size_t begin = 0, end = 0; begin < nodes.size(); begin = end)
        {
          while (end < nodes.size() && nodes[end][0] - nodes[begin][0] < tol)
            ++end;
          double integral = 0;
          for (std::size_t k = begin; k + 1 < end; ++k)
            integral += (nodes[k + 1][1] - nodes[k][1]) *
                        (nodes[k + 1][2] + nodes[k][2]) / 2.;
          const double span = nodes[end - 1][1] - nodes[begin][1];
          // + 0.: a journal at rest is written 0, not -0.
          profile.emplace_back(nodes[begin][0], -integral / span + 0.);
        }
      return profile;
    }
  } // namespace three_d
} // namespace rollnip
