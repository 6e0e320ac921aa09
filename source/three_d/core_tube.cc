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
#include <rollnip/three_d/drawn_mesh.h>
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
      /// The boundary id of a boundary face of the tube in place (Cartesian,
      /// the roll axis along z), from where all its vertices lie: builtin
      /// or gmsh vertices on the arcs to round-off (gmsh's about 1e-8 mm).
      types::boundary_id
      tube_boundary_id(const TriaAccessor<dim - 1, dim, dim> &face,
                       const Parameters::AllParameters       &parameters,
                       const Parameters::ThreeD              &three_d)
      {
        const auto  &g     = parameters.geometry;
        const double tol   = 1e-6 * g.outer_radius;
        const double alpha = g.sector_angle;
        const auto   all   = [&face](const auto &on) {
          for (unsigned int v = 0; v < face.n_vertices(); ++v)
            if (!on(face.vertex(v)))
              return false;
          return true;
        };
        const auto plane_z = [&](const double z) {
          return all(
            [=](const Point<dim> &p) { return std::abs(p[2] - z) < tol; });
        };
        // The half-plane through the axis at the angle a.
        const auto half_plane = [&](const double a) {
          return all([=](const Point<dim> &p) {
            return std::abs(p[1] * std::cos(a) - p[0] * std::sin(a)) < tol &&
                   p[0] * std::cos(a) + p[1] * std::sin(a) > 0;
          });
        };
        const auto arc = [&](const double r) {
          return all([=](const Point<dim> &p) {
            return std::abs(std::hypot(p[0], p[1]) - r) < tol;
          });
        };
        if (plane_z(0.))
          return SliceIds::near_face;
        if (plane_z(three_d.bearing_distance))
          return CoreIds::journal;
        if (plane_z(three_d.slice_thickness))
          return SliceIds::far_face; // the cover's end: the core goes on
        if (half_plane(0.))
          return SliceIds::symmetry_edge;
        if (half_plane(alpha))
          return SliceIds::far_edge;
        if (arc(three_d.core_inner_radius))
          return CoreIds::bore;
        if (arc(g.outer_radius))
          return SliceIds::outer_arc;
        AssertThrow(arc(g.inner_radius),
                    ExcMessage("the elastic core's mesh has a boundary face "
                               "on none of its surfaces, at " +
                               Parameters::number(face.center()[0]) + ", " +
                               Parameters::number(face.center()[1]) + ", " +
                               Parameters::number(face.center()[2]) + " mm"));
        return CoreIds::bare_core;
      }

      /// The builtin body: the tube's @p radial steps from @p bore_radius
      /// inside the cover's, the builtin circumferential cells, through
      /// @p planes, in place.
      void
      builtin_core_body(const Parameters::AllParameters &parameters,
                        const double                     bore_radius,
                        const std::vector<double>       &radial,
                        const unsigned int               level,
                        const std::vector<double>       &planes,
                        Triangulation<dim>              &body)
      {
        const auto         &g = parameters.geometry;
        std::vector<double> axial;
        for (unsigned int j = 1; j < planes.size(); ++j)
          axial.push_back(planes[j] - planes[j - 1]);
        auto       rad = radial;
        const auto cover =
          radial_steps(parameters, parameters.mesh.radial_grading);
        rad.insert(rad.end(), cover.begin(), cover.end());
        GridGenerator::subdivided_hyper_rectangle(
          body,
          {halved_steps(rad, level),
           halved_steps(coarse_circumferential_steps(parameters), level),
           axial},
          Point<dim>(bore_radius, 0., 0.),
          Point<dim>(g.outer_radius, g.sector_angle, planes.back()));
        bend_into_cylinder(body);
      }

      /**
       * The gmsh cross-section of Mesh/Mesh file (checked as in 2D) refined
       * @p level times in its polar chart, with the tube's cross-section
       * inside it: rings of the tube's @p radial steps (halved @p level
       * times) through the bond's own vertices, so that tube and cover share
       * every node at R1; extruded through @p planes.
       */
      void
      gmsh_core_body(const Parameters::AllParameters &parameters,
                     const std::vector<double>       &radial,
                     const unsigned int               level,
                     const std::vector<double>       &planes,
                     Triangulation<dim>              &body)
      {
        const double     R1     = parameters.geometry.inner_radius;
        const double     sector = parameters.geometry.sector_angle;
        const double     tol    = 1e-6 * parameters.geometry.outer_radius;
        Triangulation<2> cover;
        refined_gmsh_cross_section(parameters, level, cover);
        // The bond's vertices by angle, theta in (-pi/2, 3 pi/2] so that a
        // vertex at theta = 180 deg a round-off below the axis stays last.
        std::map<double, Point<2>> bond;
        for (const auto &p : cover.get_vertices())
          if (std::abs(p.norm() - R1) < tol)
            {
              double theta = std::atan2(p[1], p[0]);
              if (theta < -numbers::PI / 2)
                theta += 2 * numbers::PI;
              bond[theta] = p;
            }
        std::vector<double> radii = {R1};
        for (auto step = radial.rbegin(); step != radial.rend(); ++step)
          for (const double s : halved_steps({*step}, level))
            radii.push_back(radii.back() - s);
        // Ring k at radii[n_rings - 1 - k], from the bore out to the bond.
        const unsigned int    n_rings = radii.size();
        const unsigned int    n       = bond.size();
        std::vector<Point<2>> vertices;
        for (unsigned int k = 0; k < n_rings; ++k)
          for (const auto &[theta, p] : bond)
            {
              // In [0, sector]: no ring node a round-off below the axis,
              // where the bore's angle (core_deflection_profile()) would
              // wrap to -180 deg.
              const double t = std::clamp(theta, 0., sector);
              vertices.push_back(k + 1 == n_rings
                                   ? p
                                   : radii[n_rings - 1 - k] *
                                       Point<2>(std::cos(t), std::sin(t)));
            }
        std::vector<CellData<2>> cells;
        for (unsigned int k = 0; k + 1 < n_rings; ++k)
          for (unsigned int i = 0; i + 1 < n; ++i)
            {
              CellData<2> cell;
              cell.vertices = {k * n + i,
                               (k + 1) * n + i,
                               k * n + i + 1,
                               (k + 1) * n + i + 1};
              cells.push_back(cell);
            }
        Triangulation<2> tube, both;
        tube.create_triangulation(vertices, cells, SubCellData());
        GridGenerator::merge_triangulations(cover, tube, both, 1e-9 * R1);
        GridGenerator::extrude_triangulation(both, planes, body);
      }
    } // namespace

    void
    check_elastic_core(const Parameters::AllParameters &parameters,
                       const Parameters::ThreeD        &three_d)
    {
      AssertThrow(!is_drawn_slice(parameters),
                  ExcMessage("Three d/Core = elastic needs a cross-section "
                             "(builtin or gmsh) to mesh the tube under, but "
                             "Mesh/Mesh file '" +
                             parameters.mesh.mesh_file +
                             "' holds a 3D mesh drawn without the tube"));
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
      const double R1 = parameters.geometry.inner_radius;
      const double L  = three_d.slice_thickness;
      const double Lb = three_d.bearing_distance;
      const auto   radial =
        std::vector<double>(2, (R1 - three_d.core_inner_radius) / 2.);
      auto planes = axial_planes(L, three_d.layers, three_d.axial_grading);
      const unsigned int n_over =
        std::max<long>(1, std::lround((Lb - L) * three_d.layers / L));
      for (unsigned int j = 1; j <= n_over; ++j)
        planes.push_back(L + (Lb - L) * j / n_over);
      Triangulation<dim> body, tube;
      if (parameters.mesh.source == Parameters::MeshSource::gmsh)
        gmsh_core_body(parameters, radial, level, planes, body);
      else
        builtin_core_body(
          parameters, three_d.core_inner_radius, radial, level, planes, body);
      const std::vector<double> radii = layer_radii(parameters);
      std::set<Triangulation<dim>::active_cell_iterator> beyond_face;
      for (const auto &cell : body.active_cell_iterators())
        {
          const double r = mean_vertex_radius(cell);
          if (r > R1 && cell->center()[2] > L)
            beyond_face.insert(cell);
          cell->set_material_id(r < R1 ? parameters.material.n_layers()
                                       : layer_at_radius(radii, r));
        }
      GridGenerator::create_triangulation_with_removed_cells(body,
                                                             beyond_face,
                                                             tube);
      for (const auto &face : tube.active_face_iterators())
        if (face->at_boundary())
          face->set_boundary_id(tube_boundary_id(*face, parameters, three_d));
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
