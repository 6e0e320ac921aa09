#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <rollnip/geometry/cover_layers.h>
#include <rollnip/geometry/roll_mesh.h>
#include <rollnip/three_d/axial_grading.h>
#include <rollnip/three_d/slice_mesh.h>

#include <cmath>

namespace rollnip
{
  namespace three_d
  {
    std::vector<double>
    halved_steps(const std::vector<double> &steps, const unsigned int level)
    {
      std::vector<double> result;
      const unsigned int  n = 1u << level;
      for (const double s : steps)
        result.insert(result.end(), n, s / n);
      return result;
    }

    namespace
    {

      /// Every cell's material id: the cover layer (0 on the core) its
      /// centre's distance from the axis lies in. radial_steps() puts every
      /// interface on a cell boundary, so no cell straddles two layers.
      void
      set_slice_layer_ids(const Parameters::AllParameters &parameters,
                          Triangulation<dim>              &triangulation)
      {
        const std::vector<double> radii = layer_radii(parameters);
        for (const auto &cell : triangulation.active_cell_iterators())
          {
            const Point<dim> c = cell->center();
            cell->set_material_id(
              layer_at_radius(radii, std::hypot(c[0], c[1])));
          }
      }
    } // namespace

    void
    make_slice_mesh(const Parameters::AllParameters           &parameters,
                    const unsigned int                         level,
                    const double                               thickness,
                    const unsigned int                         layers,
                    parallel::distributed::Triangulation<dim> &triangulation,
                    const double                               axial_grading)
    {
      AssertThrow(parameters.mesh.source == Parameters::MeshSource::builtin,
                  ExcMessage("Three d: Mesh/Source must be builtin (the "
                             "slice extrudes the builtin sector annulus)"));
      const auto                            &g     = parameters.geometry;
      const std::vector<std::vector<double>> steps = {
        halved_steps(radial_steps(parameters, parameters.mesh.radial_grading),
                     level),
        halved_steps(coarse_circumferential_steps(parameters), level),
        axial_steps(thickness, layers, axial_grading)};
      // (r, theta, z) box; colorize gives ids 0..5 in the order of SliceIds.
      Triangulation<dim> coarse;
      GridGenerator::subdivided_hyper_rectangle(
        coarse,
        steps,
        Point<dim>(g.inner_radius, 0., 0.),
        Point<dim>(g.outer_radius, g.sector_angle, thickness),
        /*colorize=*/true);
      GridTools::transform(
        [](const Point<dim> &p) {
          return Point<dim>(p[0] * std::cos(p[1]), p[0] * std::sin(p[1]), p[2]);
        },
        coarse);
      coarse.set_all_manifold_ids(0);
      set_slice_layer_ids(parameters, coarse);
      triangulation.copy_triangulation(coarse);
      Tensor<1, dim> axis;
      axis[2] = 1.;
      triangulation.set_manifold(0,
                                 CylindricalManifold<dim>(axis, Point<dim>()));
    }
  } // namespace three_d
} // namespace rollnip
