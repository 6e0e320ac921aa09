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
    namespace
    {
      /// Every step of @p steps cut into 2^level equal ones.
      std::vector<double>
      halved(const std::vector<double> &steps, const unsigned int level)
      {
        std::vector<double> result;
        const unsigned int  n = 1u << level;
        for (const double s : steps)
          result.insert(result.end(), n, s / n);
        return result;
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
      AssertThrow(parameters.material.n_layers() == 1,
                  ExcMessage("Three d: Material/Layer thicknesses: layered "
                             "covers are not available in 3D yet"));
      const auto                            &g     = parameters.geometry;
      const std::vector<std::vector<double>> steps = {
        halved(radial_steps(parameters, parameters.mesh.radial_grading), level),
        halved(coarse_circumferential_steps(parameters), level),
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
      triangulation.copy_triangulation(coarse);
      Tensor<1, dim> axis;
      axis[2] = 1.;
      triangulation.set_manifold(0,
                                 CylindricalManifold<dim>(axis, Point<dim>()));
    }
  } // namespace three_d
} // namespace rollnip
