#ifndef rollnip_rolling_steady_rolling_sweep_h
#define rollnip_rolling_steady_rolling_sweep_h

#include <rollnip/parameters.h>
#include <rollnip/rolling/cover_temperature.h>
#include <rollnip/rolling/first_order_loss.h>
#include <rollnip/rolling/rolling_parameters.h>
#include <rollnip/rolling/steady_rolling.h>

#include <ostream>
#include <string>
#include <vector>

namespace rollnip
{
  /// One speed of the full steady rolling, beside the first-order route.
  struct SteadyRollingRow
  {
    SteadyRollingResult full;
    /// V tau / b with the longest time of the cover and the elastic nip's
    /// half-width b.
    double speed_over_nip = 0;
    /// F_r of the first-order route on the same mesh's elastic nip [N/mm].
    double first_order = 0;
    /// The full route's heat source (SteadyRolling::heat_source()) and the
    /// cover's temperature under it; the first-order route's temperature
    /// on the same mesh (its loss of the elastic nip at this speed).
    std::vector<CircleLoss> source;
    CoverTemperatureResult  temperature, first_order_temperature;
    /// CPU time of this speed's solve (the elastic nip's at speed 0) [s]:
    /// what benchmarks/rolling_cost.sh tabulates.
    double cpu_time = 0;
  };

  /// The first-order loss (first_order_loss()) at speed @p V [m/s] of
  /// the whole-turn @p circles of a symmetric elastic nip: their half
  /// theta >= 0, which the route mirrors; and its F_r [N/mm].
  RollingLoss
  first_order_whole_turn(const std::vector<MaterialCircle> &circles,
                         const Parameters::Rolling         &rolling,
                         const double                       R0,
                         const double                       V);

  double
  first_order_resistance(const std::vector<MaterialCircle> &circles,
                         const Parameters::Rolling         &rolling,
                         const double                       R0,
                         const double                       V);

  /// The full steady rolling's scene for the cover of @p parameters with
  /// the Prony terms of @p rolling (Rolling::validate() asks for
  /// Viscoelastic model = prony), the fine zone 2.5 @p theta0 [rad] wide
  /// on each side.
  SteadyRollingScene
  steady_rolling_scene(const Parameters::AllParameters &parameters,
                       const Parameters::Rolling       &rolling,
                       const double                     theta0);

  /**
   * The continuation in speed: the elastic nip at approach @p u0 [mm],
   * then every speed of Rolling/Full rolling speeds from the last. Stops
   * at the first speed that does not converge (its row has converged =
   * false); the rows before it stand. At every converged speed the
   * cover's temperature under the full route's heat source and under the
   * first-order route's (SteadyRollingTemperature). A line per speed to
   * @p log if given; the temperature field of each speed to
   * @p vtu_directory if not empty, as rolling_full_temperature-NN.pvtu
   * (NN the speed's number) and the series rolling_full_temperature.pvd
   * (time: the speed in the unit of Rolling/Speed unit).
   */
  std::vector<SteadyRollingRow>
  steady_rolling_sweep(const SteadyRollingScene  &scene,
                       const Parameters::Rolling &rolling,
                       const double               u0,
                       std::ostream              *log,
                       const std::string         &vtu_directory = "");

  /// rolling_full.csv (a row per speed), rolling_full_pressure.csv
  /// (p against theta at every speed) and rolling_full_profile.csv (the
  /// dissipation and the temperature over the cover's thickness at every
  /// speed) in @p directory.
  void
  write_steady_rolling(const std::vector<SteadyRollingRow> &rows,
                       const std::string                   &directory);
} // namespace rollnip

#endif
