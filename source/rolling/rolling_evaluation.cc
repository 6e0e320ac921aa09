#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>

#include <rollnip/output/atomic_file.h>
#include <rollnip/rolling/cover_circles.h>
#include <rollnip/rolling/cover_temperature.h>
#include <rollnip/rolling/radial_heat_source.h>
#include <rollnip/rolling/rolling_evaluation.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace rollnip
{
  namespace
  {
    /// The longest time of the cover's hysteresis [s].
    double
    longest_time(const Parameters::Rolling &rolling)
    {
      double t = 0;
      for (const auto &layer : rolling.layers)
        t = std::max(t, layer.longest_time());
      return t;
    }

    /// The first-order linear result sum g tau V P / R_eff [N/mm] for a
    /// one-layer cover against a rigid indenter (doc/rolling.md, R.7).
    double
    linear_estimate(const RollBody            &body,
                    const ContactResult       &nip,
                    const Parameters::Rolling &rolling,
                    const double               speed,
                    const double               indenter_radius)
    {
      if (body.materials().n_layers() != 1 || rolling.layers.size() != 1 ||
          !(indenter_radius > 0))
        return std::nan("");
      const double R0    = body.scene().geometry.outer_radius;
      const double R_eff = 1. / (1. / R0 + 1. / indenter_radius);
      return rolling.layers[0].viscous_time() * 1e3 * speed * nip.nip_load /
             R_eff;
    }
  } // namespace

  namespace
  {
    /// The speed in the user's unit, for the files and the screen.
    double
    user_speed(const Parameters::Rolling &rolling, const double v)
    {
      return rolling.in_m_per_min ? 60. * v : v;
    }

    std::string
    speed_unit(const Parameters::Rolling &rolling)
    {
      return rolling.in_m_per_min ? "m_per_min" : "m_per_s";
    }

    /// rolling_profile.csv: per circle, the dissipation (mean over a turn
    /// and peak) and the temperature, from the core out.
    void
    write_profile(const std::string                            &file,
                  const RollingLoss                            &loss,
                  const std::vector<std::pair<double, double>> &T,
                  const double                                  R0)
    {
      write_atomically(file, [&](std::ostream &out) {
        out << "r_mm,depth_below_surface_mm,layer,dissipation_mean_W_per_m3,"
               "dissipation_peak_W_per_m3,temperature_degC\n"
            << std::setprecision(8);
        for (const auto &c : loss.circles)
          out << c.radius << ',' << R0 - c.radius << ',' << c.layer << ','
              << c.mean << ',' << c.peak << ','
              << profile_temperature(T, c.radius) << '\n';
      });
    }

    /// One row of the speed table.
    struct SpeedRow
    {
      RollingLoss            loss;
      CoverTemperatureResult heat;
    };

    void
    write_speed_table(const std::string           &file,
                      const std::vector<SpeedRow> &rows,
                      const Parameters::Rolling   &rolling,
                      const double                 tau,
                      const double                 b)
    {
      write_atomically(file, [&](std::ostream &out) {
        out << "speed_" << speed_unit(rolling)
            << ",rolling_resistance_N_per_mm,drive_power_W_per_m,"
               "heat_W_per_m,bond_temperature_degC,"
               "surface_temperature_degC,max_temperature_degC,"
               "V_tau_over_b\n"
            << std::setprecision(8);
        std::vector<const SpeedRow *> sorted;
        for (const auto &r : rows)
          sorted.push_back(&r);
        std::sort(sorted.begin(), sorted.end(), [](auto a, auto b) {
          return a->loss.speed < b->loss.speed;
        });
        for (const SpeedRow *r : sorted)
          out << user_speed(rolling, r->loss.speed) << ','
              << r->loss.rolling_resistance << ',' << r->loss.power << ','
              << r->heat.generated << ',' << r->heat.bond << ','
              << r->heat.surface << ',' << r->heat.max << ','
              << 1e3 * r->loss.speed * tau / b << '\n';
      });
    }

    /// The screen lines of the headline (rank 0).
    void
    print(const RollingNumbers &n, const Parameters::Rolling &rolling)
    {
      std::cout << std::setprecision(4) << "Rolling at "
                << user_speed(rolling, n.speed) << ' '
                << (rolling.in_m_per_min ? "m/min" : "m/s")
                << " (first order): rolling resistance F_r "
                << n.rolling_resistance << " N/mm, drive power = heat "
                << n.power << " W/m of face" << std::endl
                << "Cover temperature: bond " << n.bond_temperature
                << " degC, surface " << n.surface_temperature << " degC, max "
                << n.max_temperature << " degC (heat to air " << n.heat_to_air
                << " W/m, to core " << n.heat_to_core << " W/m)" << std::endl;
    }
  } // namespace

  RollingNumbers
  evaluate_rolling(
    const RollBody                                    &body,
    const ContactResult                               &nip,
    const Parameters::Rolling                         &rolling,
    const double                                       indenter_radius,
    const RollingOutput                               &output,
    const std::function<double(double, unsigned int)> &circle_factor)
  {
    const bool root =
      Utilities::MPI::this_mpi_process(body.communicator()) == 0;
    const auto           &geometry = body.scene().geometry;
    const unsigned int    degree   = body.fe().degree;
    Timer                 clock;
    const auto            circles = cover_circles(body);
    std::vector<SpeedRow> rows;
    for (const double v : rolling.speeds)
      rows.push_back({first_order_loss(circles,
                                       rolling,
                                       geometry.outer_radius,
                                       geometry.sector_angle,
                                       v,
                                       circle_factor),
                      {}});
    RollingNumbers n;
    n.loss_seconds = clock.wall_time();
    clock.restart();
    CoverTemperature heat(body.mesh(),
                          body.mapping(),
                          degree,
                          geometry.sector_angle);
    // The first speed last, so that its field is the one written.
    for (int k = rows.size() - 1; k >= 0; --k)
      rows[k].heat =
        heat.solve(radial_heat_source(rows[k].loss.circles, degree), rolling);
    n.heat_seconds = clock.wall_time();

    const SpeedRow &main               = rows.front();
    n.available                        = true;
    n.speed                            = main.loss.speed;
    n.rolling_resistance               = main.loss.rolling_resistance;
    n.power                            = main.loss.power;
    static_cast<CoverHeatBalance &>(n) = main.heat.heat_balance();
    const double tau                   = longest_time(rolling);
    n.speed_over_nip                   = 1e3 * n.speed * tau / nip.half_chord;
    n.linear_estimate =
      linear_estimate(body, nip, rolling, n.speed, indenter_radius);
    const std::string &directory = output.directory;
    if (output.write_vtu)
      heat.write_vtu(directory, "temperature");
    if (output.write_csv)
      {
        if (root)
          {
            write_profile(directory + "/rolling_profile.csv",
                          main.loss,
                          main.heat.profile,
                          geometry.outer_radius);
            if (rows.size() > 1)
              write_speed_table(directory + "/rolling_speeds.csv",
                                rows,
                                rolling,
                                tau,
                                nip.half_chord);
          }
      }
    if (root)
      {
        print(n, rolling);
        // First order in V tau / b: the loss of a Maxwell branch peaks
        // near V tau ~ b and falls beyond, where this route keeps rising.
        const double fastest =
          *std::max_element(rolling.speeds.begin(), rolling.speeds.end());
        const double ratio = 1e3 * fastest * tau / nip.half_chord;
        if (ratio > 0.1)
          std::cerr << "rollnip: warning: Rolling: V tau / b = "
                    << std::setprecision(3) << ratio << " at "
                    << user_speed(rolling, fastest) << ' '
                    << (rolling.in_m_per_min ? "m/min" : "m/s")
                    << " (tau = " << tau << " s, b = " << nip.half_chord
                    << " mm): the first-order loss needs V tau << b and "
                       "overestimates it here"
                    << std::endl;
      }
    return n;
  }

  void
  write_heat_lines(std::ostream           &out,
                   const std::string      &prefix,
                   const CoverHeatBalance &heat)
  {
    out << prefix << "cover_bond_temperature_degC = " << heat.bond_temperature
        << '\n'
        << prefix
        << "cover_surface_temperature_degC = " << heat.surface_temperature
        << '\n'
        << prefix << "cover_max_temperature_degC = " << heat.max_temperature
        << '\n'
        << prefix << "heat_generated_W_per_m = " << heat.heat_generated << '\n'
        << prefix << "heat_to_air_W_per_m = " << heat.heat_to_air << '\n'
        << prefix << "heat_to_core_W_per_m = " << heat.heat_to_core << '\n';
  }

  std::string
  rolling_lines(const RollingNumbers &n)
  {
    std::ostringstream out;
    out << std::setprecision(8)
        << "# rolling, first order in V tau / b (doc/rolling.md)\n"
        << "rolling_speed_m_per_s = " << n.speed << '\n'
        << "rolling_resistance_N_per_mm = " << n.rolling_resistance << '\n'
        << "rolling_drive_power_W_per_m = " << n.power << '\n'
        << "rolling_heat_W_per_m = " << n.power << '\n'
        << "rolling_linear_estimate_N_per_mm = " << n.linear_estimate << '\n'
        << "rolling_V_tau_over_b = " << n.speed_over_nip << '\n';
    write_heat_lines(out, "", n);
    out << "rolling_loss_wall_time_s = " << n.loss_seconds << '\n'
        << "rolling_temperature_wall_time_s = " << n.heat_seconds << '\n';
    return out.str();
  }
} // namespace rollnip
