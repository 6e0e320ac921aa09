#include <deal.II/base/numbers.h>

#include <rollnip/rolling/radial_heat_source.h>
#include <rollnip/rolling/steady_rolling_temperature.h>

namespace rollnip
{
  namespace
  {
    /// @p mesh made the whole annulus of @p annulus.
    parallel::distributed::Triangulation<dim> &
    annulus_mesh(parallel::distributed::Triangulation<dim> &mesh,
                 const AnnulusMesh                         &annulus)
    {
      annulus.create(mesh);
      return mesh;
    }
  } // namespace

  SteadyRollingTemperature::SteadyRollingTemperature(const AnnulusMesh &annulus)
      : mesh(MPI_COMM_SELF)
      , mapping(1)
      , temperature(annulus_mesh(mesh, annulus), mapping, 1, 2 * numbers::PI)
  {}

  CoverTemperatureResult
  SteadyRollingTemperature::solve(const std::vector<CircleLoss> &circles,
                                  const Parameters::Rolling     &rolling)
  {
    return temperature.solve(radial_heat_source(circles, 1), rolling);
  }

  void
  SteadyRollingTemperature::write_vtu(const std::string &directory,
                                      const std::string &name) const
  {
    temperature.write_vtu(directory, name);
  }
} // namespace rollnip
