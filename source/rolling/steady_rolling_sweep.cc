#include <deal.II/base/data_out_base.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <rollnip/geometry/cover_layers.h>
#include <rollnip/output/atomic_file.h>
#include <rollnip/rolling/first_order_loss.h>
#include <rollnip/rolling/steady_rolling_sweep.h>
#include <rollnip/rolling/steady_rolling_temperature.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace rollnip
{
  RollingLoss
  first_order_whole_turn(const std::vector<MaterialCircle> &circles,
                         const Parameters::Rolling         &rolling,
                         const double                       R0,
                         const double                       V)
  {
    std::vector<MaterialCircle> half;
    for (const auto &c : circles)
      {
        MaterialCircle h = c;
        h.samples.clear();
        for (const auto &s : c.samples)
          if (s.theta >= 0)
            h.samples.push_back(s);
        half.push_back(std::move(h));
      }
    return first_order_loss(half, rolling, R0, numbers::PI, V);
  }

  double
  first_order_resistance(const std::vector<MaterialCircle> &circles,
                         const Parameters::Rolling         &rolling,
                         const double                       R0,
                         const double                       V)
  {
    return first_order_whole_turn(circles, rolling, R0, V).rolling_resistance;
  }

  SteadyRollingScene
  steady_rolling_scene(const Parameters::AllParameters &parameters,
                       const Parameters::Rolling       &rolling,
                       const double                     theta0)
  {
    SteadyRollingScene s;
    s.material               = parameters.material;
    s.viscous                = rolling.layers;
    s.indenter_radius        = parameters.contact.indenter_radius;
    s.layout.layer_radii     = layer_radii(parameters);
    s.layout.fine_half_angle = 2.5 * theta0;
    s.layout.fine_cells      = 2 * (rolling.full_nip_cells / 2);
    // The steps beyond the fine zone refine with it (1.05 at 100 cells).
    s.layout.growth         = 1 + 5. / s.layout.fine_cells;
    s.layout.radial_cells   = rolling.full_radial_cells;
    s.layout.radial_grading = 0.3;
    return s;
  }

  namespace
  {
    /// The screen line of @p row.
    void
    log_line(std::ostream &log, const SteadyRollingRow &row)
    {
      const auto &r = row.full;
      log << "Full steady rolling: V = " << r.speed * 60
          << " m/min, V tau/b = " << row.speed_over_nip << ": ";
      if (!r.converged)
        {
          log << "did not converge; the continuation stops" << std::endl;
          return;
        }
      log << "F_r = " << r.resistance_energy << " N/mm (moment "
          << r.resistance_moment << ", first order " << row.first_order
          << "), P = " << r.load << " N/mm; T bond " << row.temperature.bond
          << ", surface " << row.temperature.surface << ", max "
          << row.temperature.max << " degC (first order "
          << row.first_order_temperature.max << ")" << std::endl;
    }

    /// The screen line of @p row, six digits.
    void
    log_row(std::ostream &screen, const SteadyRollingRow &row)
    {
      std::ostringstream log;
      log << std::setprecision(6);
      log_line(log, row);
      screen << log.str() << std::flush;
    }

    /// The series of the temperature fields of @p rows, named as
    /// steady_rolling_sweep() writes them.
    void
    write_temperature_series(const std::vector<SteadyRollingRow> &rows,
                             const Parameters::Rolling           &rolling,
                             const std::string                   &directory)
    {
      std::vector<std::pair<double, std::string>> times;
      for (unsigned int k = 0; k < rows.size(); ++k)
        if (rows[k].full.converged)
          times.emplace_back(rows[k].full.speed *
                               (rolling.in_m_per_min ? 60. : 1.),
                             "rolling_full_temperature-" +
                               Utilities::int_to_string(k + 1, 2) + ".pvtu");
      write_atomically(directory + "/rolling_full_temperature.pvd",
                       [&](std::ostream &out) {
                         DataOutBase::write_pvd_record(out, times);
                       });
    }
  } // namespace

  std::vector<SteadyRollingRow>
  steady_rolling_sweep(const SteadyRollingScene  &scene,
                       const Parameters::Rolling &rolling,
                       const double               u0,
                       std::ostream              *log,
                       const std::string         &vtu_directory)
  {
    SteadyRolling                 model(scene);
    SteadyRollingTemperature      heat(model.annulus());
    std::vector<SteadyRollingRow> rows;
    Timer                         timer;
    AssertThrow(model.solve_elastic(u0, 4),
                ExcMessage("Full steady rolling: the elastic whole-circle "
                           "nip did not converge"));
    const double elastic_time = timer.cpu_time();
    const auto   circles      = model.circles();
    const auto   still        = model.result();
    const double R0           = scene.layout.layer_radii.back();
    double       tau          = 0;
    for (const auto &layer : rolling.layers)
      tau = std::max(tau, layer.longest_time());
    for (const double V : rolling.full_speeds)
      {
        SteadyRollingRow row;
        timer.restart();
        row.full.converged = V == 0 ? true : model.solve_speed(V);
        row.cpu_time       = V == 0 ? elastic_time : timer.cpu_time();
        if (row.full.converged)
          row.full = V == 0 ? still : model.result();
        row.full.speed     = V;
        row.speed_over_nip = V * 1e3 * tau / still.half_width;
        const RollingLoss first =
          first_order_whole_turn(circles, rolling, R0, V);
        row.first_order = first.rolling_resistance;
        if (row.full.converged)
          {
            row.source                  = model.heat_source();
            row.first_order_temperature = heat.solve(first.circles, rolling);
            row.temperature             = heat.solve(row.source, rolling);
            if (!vtu_directory.empty())
              heat.write_vtu(vtu_directory,
                             "rolling_full_temperature-" +
                               Utilities::int_to_string(rows.size() + 1, 2));
          }
        rows.push_back(row);
        if (log)
          log_row(*log, row);
        if (!row.full.converged)
          break;
      }
    if (!vtu_directory.empty())
      write_temperature_series(rows, rolling, vtu_directory);
    return rows;
  }

  namespace
  {
    /// rolling_full_profile.csv: per converged speed and circle, the mean
    /// dissipation and the temperature of the full and the first-order
    /// route, from the core out.
    void
    write_profile(const std::vector<SteadyRollingRow> &rows,
                  const std::string                   &file)
    {
      write_atomically(file, [&](std::ostream &out) {
        out << "speed_m_per_min,r_mm,depth_below_surface_mm,layer,"
               "dissipation_mean_W_per_m3,temperature_degC,"
               "temperature_first_order_degC\n"
            << std::setprecision(8);
        for (const auto &row : rows)
          {
            if (row.source.empty())
              continue;
            const double R0 = row.temperature.profile.back().first;
            for (const auto &c : row.source)
              out << row.full.speed * 60 << ',' << c.radius << ','
                  << R0 - c.radius << ',' << c.layer << ',' << c.mean << ','
                  << profile_temperature(row.temperature.profile, c.radius)
                  << ','
                  << profile_temperature(row.first_order_temperature.profile,
                                         c.radius)
                  << '\n';
          }
      });
    }
  } // namespace

  void
  write_steady_rolling(const std::vector<SteadyRollingRow> &rows,
                       const std::string                   &directory)
  {
    constexpr double deg = 180. / numbers::PI;
    write_atomically(directory + "/rolling_full.csv", [&](std::ostream &out) {
      out << "speed_m_per_min,speed_m_per_s,V_tau_over_b,P_N_per_mm,"
             "F_r_moment_N_per_mm,F_r_energy_N_per_mm,"
             "F_r_first_order_N_per_mm,full_over_first_order,theta_in_deg,"
             "theta_out_deg,nip_shift_deg,peak_pressure_MPa,"
             "peak_position_deg,power_W_per_m,fixed_point_iterations,"
             "converged,cpu_time_s,heat_W_per_m,bond_temperature_degC,"
             "surface_temperature_degC,max_temperature_degC,"
             "heat_to_air_W_per_m,heat_to_core_W_per_m,"
             "max_temperature_first_order_degC\n"
          << std::setprecision(8);
      for (const auto &row : rows)
        {
          const auto &r = row.full;
          out << r.speed * 60 << ',' << r.speed << ',' << row.speed_over_nip
              << ',' << r.load << ',' << r.resistance_moment << ','
              << r.resistance_energy << ',' << row.first_order << ','
              << (row.first_order > 0 ? r.resistance_energy / row.first_order
                                      : 1.)
              << ',' << r.theta_in * deg << ',' << r.theta_out * deg << ','
              << r.pressure_centre * deg << ',' << r.peak_pressure << ','
              << r.peak_position * deg << ',' << r.power << ','
              << r.fixed_point_iterations << ',' << (r.converged ? 1 : 0) << ','
              << row.cpu_time << ',';
          const auto &T = row.temperature;
          if (r.converged)
            out << T.generated << ',' << T.bond << ',' << T.surface << ','
                << T.max << ',' << T.to_air << ',' << T.to_core << ','
                << row.first_order_temperature.max << '\n';
          else
            out << "nan,nan,nan,nan,nan,nan,nan\n";
        }
    });
    write_atomically(directory + "/rolling_full_pressure.csv",
                     [&](std::ostream &out) {
                       out << "speed_m_per_min,theta_deg,pressure_MPa\n"
                           << std::setprecision(8);
                       for (const auto &row : rows)
                         {
                           for (const auto &[theta, p] : row.full.pressure)
                             out << row.full.speed * 60 << ',' << theta * deg
                                 << ',' << p << '\n';
                         }
                     });
    write_profile(rows, directory + "/rolling_full_profile.csv");
  }
} // namespace rollnip
