#ifndef rollnip_rolling_steady_rolling_temperature_h
#define rollnip_rolling_steady_rolling_temperature_h

#include <deal.II/distributed/tria.h>

#include <deal.II/fe/mapping_q.h>

#include <rollnip/rolling/annulus_mesh.h>
#include <rollnip/rolling/cover_temperature.h>
#include <rollnip/rolling/first_order_loss.h>
#include <rollnip/rolling/rolling_parameters.h>

#include <string>
#include <vector>

namespace rollnip
{
  /**
   * The cover's steady temperature under the full steady rolling's heat
   * source (doc/rolling.md, section 7): the conduction solve of the
   * first-order route (CoverTemperature: same boundary conditions and
   * inputs of Rolling) on the full rolling's own whole-circle mesh, Q1, on
   * this process alone (the full rolling is serial). Its rings are those
   * of the source's circles, so the heat made is the dissipated power of
   * the circles to round-off.
   */
  class SteadyRollingTemperature
  {
  public:
    explicit SteadyRollingTemperature(const AnnulusMesh &annulus);

    /// The temperature for the mean dissipation @p circles of a
    /// SteadyRolling on @p annulus (SteadyRolling::heat_source(), or the
    /// first-order loss of its circles).
    CoverTemperatureResult
    solve(const std::vector<CircleLoss> &circles,
          const Parameters::Rolling     &rolling);

    /// The last temperature as @p directory/@p name.pvtu (one piece).
    void
    write_vtu(const std::string &directory, const std::string &name) const;

  private:
    parallel::distributed::Triangulation<dim> mesh;
    MappingQ<dim>                             mapping;
    CoverTemperature                          temperature;
  };
} // namespace rollnip

#endif
