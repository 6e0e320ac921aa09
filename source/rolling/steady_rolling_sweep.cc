#include <deal.II/base/timer.h>

#include <rollnip/geometry/cover_layers.h>
#include <rollnip/output/atomic_file.h>
#include <rollnip/rolling/first_order_loss.h>
#include <rollnip/rolling/steady_rolling_sweep.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace rollnip
{
  double
  first_order_resistance(const std::vector<MaterialCircle> &circles,
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
    return first_order_loss(half, rolling, R0, numbers::PI, V)
      .rolling_resistance;
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

  std::vector<SteadyRollingRow>
  steady_rolling_sweep(const SteadyRollingScene  &scene,
                       const Parameters::Rolling &rolling,
                       const double               u0,
                       std::ostream              *log)
  {
    SteadyRolling                 model(scene);
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
        row.first_order    = first_order_resistance(circles, rolling, R0, V);
        rows.push_back(row);
        if (log)
          *log << "Full steady rolling: V = " << V * 60
               << " m/min, V tau/b = " << row.speed_over_nip << ": "
               << (row.full.converged
                     ? "F_r = " + std::to_string(row.full.resistance_energy) +
                         " N/mm (moment " +
                         std::to_string(row.full.resistance_moment) +
                         ", first order " + std::to_string(row.first_order) +
                         "), P = " + std::to_string(row.full.load) + " N/mm"
                     : std::string("did not converge; the continuation stops"))
               << std::endl;
        if (!row.full.converged)
          break;
      }
    return rows;
  }

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
             "converged,cpu_time_s\n"
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
              << row.cpu_time << '\n';
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
  }
} // namespace rollnip
