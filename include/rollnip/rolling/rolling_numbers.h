#ifndef rollnip_rolling_rolling_numbers_h
#define rollnip_rolling_rolling_numbers_h

#include <rollnip/rolling/thermal_softening.h>

#include <limits>
#include <ostream>
#include <string>

namespace rollnip
{
  /// A cover's temperatures and heat balance, as the first-order, the
  /// mating roll's and the full steady rolling each report them.
  struct CoverHeatBalance
  {
    /// Mean on the bond and the surface, largest [degC].
    double bond_temperature = 0, surface_temperature = 0, max_temperature = 0;
    /// The heat balance of the temperature solution [W/m].
    double heat_generated = 0, heat_to_air = 0, heat_to_core = 0;
  };

  /// The six summary.txt lines of @p heat, each name led by @p prefix
  /// ("", "mate_", "full_").
  void
  write_heat_lines(std::ostream           &out,
                   const std::string      &prefix,
                   const CoverHeatBalance &heat);

  /// The covered mating roll's own loss and temperature at the same
  /// surface speed (doc/rolling.md), in the engineer's units.
  struct MateRolling : CoverHeatBalance
  {
    bool   available          = false;
    double rolling_resistance = 0; ///< its loss / V [N/mm]
    double power              = 0; ///< dissipated in its cover [W/m]
    double speed_over_nip     = 0; ///< V tau / b with its longest time
  };

  /// The full steady rolling's loss and cover temperature at Rolling/
  /// Surface speed (doc/rolling.md, section 7), and the hottest of its
  /// speeds, in the engineer's units.
  struct FullRolling : CoverHeatBalance
  {
    bool   ran                = false; ///< a full speed converged
    bool   available          = false; ///< Surface speed is a full speed
    double speed              = 0;     ///< [m/s]
    double rolling_resistance = 0;     ///< dissipation / V [N/mm]
    double power              = 0;     ///< dissipated = drive power [W/m]
    double load               = 0;     ///< P at the nip's approach [N/mm]
    /// The converged full speed with the largest cover temperature [m/s]
    /// and that temperature [degC].
    double hottest_speed = 0, hottest_temperature = 0;
  };

  /// What the rolling post-process reports of one nip at Rolling/Surface
  /// speed (doc/rolling.md), in the engineer's units.
  struct RollingNumbers : CoverHeatBalance
  {
    bool   available = false;
    double speed     = 0; ///< [m/s]
    /// Rolling resistance F_r = drive power / V [N/mm].
    double rolling_resistance = 0;
    /// Drive power = dissipated power = heat made [W per m of face].
    double power = 0;
    /// V tau / b with the longest time of the cover (<< 1 for the first
    /// order to hold).
    double speed_over_nip = 0;
    /// sum g_i tau_i V P / R_eff [N/mm], the linear first-order result of
    /// a one-layer cover against a rigid indenter (nan otherwise).
    double linear_estimate = std::numeric_limits<double>::quiet_NaN();
    /// Wall times [s]: the loss (sampling the circles, all speeds), the
    /// temperatures (all speeds).
    double loss_seconds = 0, heat_seconds = 0;
    /// The fixed point with the cover's temperature, if its modulus or
    /// times depend on it.
    ThermalCoupling thermal;
    /// The covered mating roll's own loss, if there is one.
    MateRolling mate;
    /// The full steady rolling's, if Rolling/Full steady rolling.
    FullRolling full;
  };
} // namespace rollnip

#endif
