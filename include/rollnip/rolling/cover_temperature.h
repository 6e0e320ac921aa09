#ifndef rollnip_rolling_cover_temperature_h
#define rollnip_rolling_cover_temperature_h

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping.h>

#include <deal.II/lac/trilinos_vector.h>

#include <rollnip/global.h>
#include <rollnip/rolling/rolling_numbers.h>
#include <rollnip/rolling/rolling_parameters.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace rollnip
{
  /// The cover's steady temperature and its heat balance (doc/rolling.md).
  struct CoverTemperatureResult
  {
    double bond    = 0; ///< mean on the bond r = R1 [degC]
    double surface = 0; ///< mean on the surface r = R0 [degC]
    double max     = 0; ///< largest nodal value [degC]
    /// Heat made in the cover, and leaving through the surface to the air
    /// and into the core (the consistent flux of the fixed core), for the
    /// whole roll [W/m of face].
    double generated = 0, to_air = 0, to_core = 0;
    /// (r [mm], T [degC]) at the nodes on the line of centres, by radius.
    std::vector<std::pair<double, double>> profile;

    /// The temperatures and the heat balance as a report carries them.
    CoverHeatBalance
    heat_balance() const
    {
      CoverHeatBalance h;
      h.bond_temperature    = bond;
      h.surface_temperature = surface;
      h.max_temperature     = max;
      h.heat_generated      = generated;
      h.heat_to_air         = to_air;
      h.heat_to_core        = to_core;
      return h;
    }
  };

  /// T [degC] at radius @p r [mm] of a (r, T) @p profile sorted by r
  /// (CoverTemperatureResult::profile): linear between its nodes, constant
  /// beyond its ends, NaN when it is empty.
  double
  profile_temperature(const std::vector<std::pair<double, double>> &profile,
                      const double                                  r);

  /**
   * Steady conduction in the cover, -div(k grad T) = s, on the cover's own
   * mesh with FE_Q of the displacement's degree: the core held at
   * Rolling/Core temperature or insulated, the surface cooled to the air,
   * -k dT/dn = h (T - T_air), the sector's edges insulated (the source is
   * the circumferential mean, so the field is axisymmetric). Lengths in
   * mm; k per layer by the cells' material ids.
   */
  class CoverTemperature
  {
  public:
    CoverTemperature(const parallel::distributed::Triangulation<dim> &mesh,
                     const Mapping<dim>                              &mapping,
                     const unsigned int                               degree,
                     const double sector_angle);

    /// Solves for the source @p source(r) [W/m^3] (collective).
    CoverTemperatureResult
    solve(const std::function<double(double)> &source,
          const Parameters::Rolling           &rolling);

    /// The temperature as @p directory/@p name.pvtu with one .vtu piece
    /// per process (collective).
    void
    write_vtu(const std::string &directory, const std::string &name) const;

  private:
    const parallel::distributed::Triangulation<dim> &mesh;
    const Mapping<dim>                              &mapping;
    const FE_Q<dim>                                  fe;
    DoFHandler<dim>                                  dofs;
    const double                                     sector_angle;
    TrilinosWrappers::MPI::Vector                    temperature; ///< ghosted
  };
} // namespace rollnip

#endif
