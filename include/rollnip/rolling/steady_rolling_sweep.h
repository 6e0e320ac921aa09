#ifndef rollnip_rolling_steady_rolling_sweep_h
#define rollnip_rolling_steady_rolling_sweep_h

#include <rollnip/parameters.h>
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
    /// CPU time of this speed's solve (the elastic nip's at speed 0) [s]:
    /// what benchmarks/rolling_cost.sh tabulates.
    double cpu_time = 0;
  };

  /// F_r [N/mm] of the first-order route (first_order_loss()) at speed
  /// @p V [m/s] for the whole-turn @p circles of a symmetric elastic nip:
  /// their half theta >= 0, which the route mirrors.
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
   * false); the rows before it stand. A line per speed to @p log if given.
   */
  std::vector<SteadyRollingRow>
  steady_rolling_sweep(const SteadyRollingScene  &scene,
                       const Parameters::Rolling &rolling,
                       const double               u0,
                       std::ostream              *log);

  /// rolling_full.csv (a row per speed) and rolling_full_pressure.csv
  /// (p against theta, a column pair per speed) in @p directory.
  void
  write_steady_rolling(const std::vector<SteadyRollingRow> &rows,
                       const std::string                   &directory);
} // namespace rollnip

#endif
