#include <rollnip/rolling/steady_rolling_report.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace rollnip
{
  FullRolling
  full_rolling_numbers(const std::vector<SteadyRollingRow> &rows,
                       const double                         surface_speed)
  {
    FullRolling f;
    for (const auto &row : rows)
      {
        if (!row.full.converged)
          continue;
        const auto &T = row.temperature;
        if (!f.ran || T.max > f.hottest_temperature)
          {
            f.hottest_speed       = row.full.speed;
            f.hottest_temperature = T.max;
          }
        f.ran = true;
        if (std::abs(row.full.speed - surface_speed) >
            1e-12 * std::abs(surface_speed))
          continue;
        f.available                        = true;
        f.speed                            = row.full.speed;
        f.rolling_resistance               = row.full.resistance_energy;
        f.power                            = row.full.power;
        f.load                             = row.full.load;
        static_cast<CoverHeatBalance &>(f) = T.heat_balance();
      }
    return f;
  }

  std::string
  full_rolling_lines(const RollingNumbers &n)
  {
    const FullRolling &f = n.full;
    if (!f.ran)
      return "";
    std::ostringstream out;
    out << std::setprecision(8)
        << "# full steady rolling at the nip's approach (doc/rolling.md, "
           "section 7)\n";
    if (f.available)
      {
        out << "full_rolling_speed_m_per_s = " << f.speed << '\n'
            << "full_rolling_resistance_N_per_mm = " << f.rolling_resistance
            << '\n'
            << "full_rolling_drive_power_W_per_m = " << f.power << '\n'
            << "full_rolling_load_N_per_mm = " << f.load << '\n';
        write_heat_lines(out, "full_", f);
      }
    out << "full_rolling_hottest_speed_m_per_s = " << f.hottest_speed << '\n'
        << "full_rolling_hottest_max_temperature_degC = "
        << f.hottest_temperature << '\n';
    return out.str();
  }
} // namespace rollnip
