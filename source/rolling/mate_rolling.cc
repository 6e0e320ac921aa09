#include <rollnip/rolling/cover_circles.h>
#include <rollnip/rolling/cover_temperature.h>
#include <rollnip/rolling/first_order_loss.h>
#include <rollnip/rolling/mate_rolling.h>
#include <rollnip/rolling/radial_heat_source.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace rollnip
{
  MateRolling
  evaluate_mate_rolling(const RollBody            &mate,
                        const Parameters::Rolling &mate_rolling,
                        const double               half_chord)
  {
    const auto                  &geometry = mate.scene().geometry;
    const unsigned int           degree   = mate.fe().degree;
    const RollingLoss            loss = first_order_loss(cover_circles(mate),
                                              mate_rolling,
                                              geometry.outer_radius,
                                              geometry.sector_angle,
                                              mate_rolling.speed);
    CoverTemperature             heat(mate.mesh(),
                          mate.mapping(),
                          degree,
                          geometry.sector_angle);
    const CoverTemperatureResult T =
      heat.solve(radial_heat_source(loss.circles, degree), mate_rolling);
    MateRolling m;
    m.available                        = true;
    m.rolling_resistance               = loss.rolling_resistance;
    m.power                            = loss.power;
    static_cast<CoverHeatBalance &>(m) = T.heat_balance();
    double tau                         = 0;
    for (const auto &layer : mate_rolling.layers)
      tau = std::max(tau, layer.longest_time());
    m.speed_over_nip = 1e3 * mate_rolling.speed * tau / half_chord;
    return m;
  }

  std::string
  mate_rolling_lines(const RollingNumbers &n)
  {
    const MateRolling &m = n.mate;
    std::ostringstream out;
    out << std::setprecision(8);
    if (!m.available)
      {
        out << "# the mating roll is rigid: no loss of its own\n"
            << "mate_rolling_resistance_N_per_mm = 0\n"
            << "mate_drive_power_W_per_m = 0\n"
            << "pair_drive_power_W_per_m = " << n.power << '\n';
        return out.str();
      }
    out << "# the covered mating roll's own loss, first order, same "
           "surface speed (doc/rolling.md)\n"
        << "mate_rolling_resistance_N_per_mm = " << m.rolling_resistance << '\n'
        << "mate_drive_power_W_per_m = " << m.power << '\n'
        << "mate_V_tau_over_b = " << m.speed_over_nip << '\n';
    write_heat_lines(out, "mate_", m);
    out << "pair_rolling_resistance_N_per_mm = "
        << n.rolling_resistance + m.rolling_resistance << '\n'
        << "pair_drive_power_W_per_m = " << n.power + m.power << '\n';
    return out.str();
  }
} // namespace rollnip
