#include <deal.II/base/mpi.h>

#include <rollnip/rolling/cover_circles.h>
#include <rollnip/rolling/cover_temperature.h>
#include <rollnip/rolling/first_order_loss.h>
#include <rollnip/rolling/radial_heat_source.h>
#include <rollnip/rolling/thermal_fixed_point.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace rollnip
{
  namespace
  {
    using Profile = std::vector<std::pair<double, double>>;

    /// One pass's loss and temperature at the main speed.
    struct Pass
    {
      RollingLoss            loss;
      CoverTemperatureResult heat;
    };

    Pass
    loss_and_temperature(const RollBody            &body,
                         const Parameters::Rolling &rolling,
                         const CircleFactor        &factor)
    {
      const auto        &geometry = body.scene().geometry;
      const unsigned int degree   = body.fe().degree;
      Pass               pass;
      pass.loss = first_order_loss(cover_circles(body),
                                   rolling,
                                   geometry.outer_radius,
                                   geometry.sector_angle,
                                   rolling.speed,
                                   factor);
      CoverTemperature heat(body.mesh(),
                            body.mapping(),
                            degree,
                            geometry.sector_angle);
      pass.heat =
        heat.solve(radial_heat_source(pass.loss.circles, degree), rolling);
      return pass;
    }

    /// The largest nodal change between two profiles of the same mesh.
    double
    largest_change(const Profile &a, const Profile &b)
    {
      AssertThrow(a.size() == b.size(), ExcInternalError());
      double change = 0;
      for (std::size_t i = 0; i < a.size(); ++i)
        change = std::max(change, std::abs(a[i].second - b[i].second));
      return change;
    }

    /**
     * Aitken's relaxation of the fixed point T = G(T) on the nodal
     * temperatures: T += omega (G(T) - T), omega from the last two
     * residuals (1 at first). A steep WLF shift makes G fall fast with T
     * (a warmer cover loses much less), and the plain iteration then
     * swings between a cold and a hot state; the relaxation damps it.
     */
    struct AitkenRelaxation
    {
      std::vector<double> last_residual;
      double              omega = 1;

      void
      step(Profile &T, const Profile &G)
      {
        std::vector<double> r(T.size());
        for (std::size_t i = 0; i < T.size(); ++i)
          r[i] = G[i].second - T[i].second;
        if (!last_residual.empty())
          {
            double num = 0, den = 0;
            for (std::size_t i = 0; i < r.size(); ++i)
              {
                const double dr = r[i] - last_residual[i];
                num += last_residual[i] * dr;
                den += dr * dr;
              }
            if (den > 0)
              omega = std::clamp(-omega * num / den, 0.05, 1.5);
          }
        for (std::size_t i = 0; i < T.size(); ++i)
          T[i].second += omega * r[i];
        last_residual = std::move(r);
      }
    };

    /// Sets the roll's moduli and the circles' loss factor from the
    /// temperature @p T; records the modulus factor's range.
    void
    soften(RollBody                           &body,
           const Parameters::ThermalSoftening &softening,
           const Profile                      &T,
           CircleFactor                       &circle_factor,
           ThermalCoupling                    &coupling)
    {
      body.materials().set_modulus_factor(
        [softening, T](const Point<dim> &X, const types::material_id id) {
          return softening.modulus_factor(id, profile_temperature(T, X.norm()));
        });
      circle_factor = [softening, T](const double r, const unsigned int l) {
        const double t = profile_temperature(T, r);
        return softening.modulus_factor(l, t) * softening.time_shift(l, t);
      };
      coupling.min_modulus_factor = std::numeric_limits<double>::max();
      coupling.max_modulus_factor = 0;
      const unsigned int n_layers = body.materials().n_layers();
      for (const auto &[r, t] : T)
        for (unsigned int l = 0; l < n_layers; ++l)
          {
            const double f = softening.modulus_factor(l, t);
            coupling.min_modulus_factor =
              std::min(coupling.min_modulus_factor, f);
            coupling.max_modulus_factor =
              std::max(coupling.max_modulus_factor, f);
          }
    }
  } // namespace

  ContactResult
  soften_to_fixed_point(
    RollBody                                                  &body,
    const ContactResult                                       &nip,
    const Parameters::Rolling                                 &rolling,
    const std::function<ContactResult(const ContactResult &)> &resolve,
    ThermalCoupling                                           &coupling,
    CircleFactor                                              &circle_factor)
  {
    const auto &softening = rolling.softening;
    coupling              = ThermalCoupling();
    coupling.active       = true;
    circle_factor         = {};
    body.materials().set_modulus_factor({});
    Pass pass = loss_and_temperature(body, rolling, circle_factor);
    coupling.constant_width              = 2. * nip.half_chord;
    coupling.constant_rolling_resistance = pass.loss.rolling_resistance;
    coupling.constant_bond               = pass.heat.bond;
    coupling.constant_surface            = pass.heat.surface;
    coupling.constant_max                = pass.heat.max;

    ContactResult result = nip;
    const bool    root =
      Utilities::MPI::this_mpi_process(body.communicator()) == 0;
    Profile          T = pass.heat.profile; // the iterate
    AitkenRelaxation relaxation;
    while (coupling.iterations < softening.max_iterations)
      {
        soften(body, softening, T, circle_factor, coupling);
        // Times that shift alone change the loss, not the nip.
        if (coupling.max_modulus_factor != 1. ||
            coupling.min_modulus_factor != 1.)
          result = resolve(result);
        AssertThrow(result.converged,
                    ExcMessage("Rolling/Temperature dependence: the nip of "
                               "the softened cover did not converge (pass " +
                               std::to_string(coupling.iterations + 1) +
                               "): " + result.message));
        ++coupling.iterations;
        pass = loss_and_temperature(body, rolling, circle_factor);
        coupling.temperature_changes.push_back(
          largest_change(T, pass.heat.profile));
        const auto &dT       = coupling.temperature_changes;
        coupling.contraction = dT.size() > 1 && dT[dT.size() - 2] > 0
                                 ? dT.back() / dT[dT.size() - 2]
                                 : std::numeric_limits<double>::quiet_NaN();
        if (root)
          std::cout << "Thermal softening, pass " << coupling.iterations
                    << ": nip width " << std::setprecision(6)
                    << 2. * result.half_chord << " mm, F_r "
                    << pass.loss.rolling_resistance << " N/mm, T max "
                    << pass.heat.max << " degC, largest change "
                    << std::setprecision(3) << dT.back() << " K (relaxation "
                    << relaxation.omega << ")" << std::endl;
        if (dT.back() <= softening.tolerance)
          {
            coupling.converged = true;
            break;
          }
        relaxation.step(T, pass.heat.profile);
      }
    coupling.width = 2. * result.half_chord;
    if (root && !coupling.converged)
      std::cerr << "rollnip: warning: Rolling/Temperature dependence: no "
                   "fixed point of nip and temperature within "
                << softening.max_iterations << " passes (largest change "
                << coupling.temperature_changes.back()
                << " K); the numbers are those of the last pass" << std::endl;
    return result;
  }

  std::string
  thermal_lines(const RollingNumbers &n)
  {
    const ThermalCoupling &t = n.thermal;
    if (!t.active)
      return "";
    auto change = [](const double now, const double before) {
      return 100. * (now / before - 1.);
    };
    std::ostringstream out;
    out << std::setprecision(8)
        << "# cover softened by its temperature: fixed point of nip, loss, "
           "temperature and modulus (doc/rolling.md)\n"
        << "thermal_passes = " << t.iterations << '\n'
        << "thermal_converged = " << (t.converged ? "true" : "false") << '\n'
        << "thermal_largest_change_K = "
        << (t.temperature_changes.empty() ? 0. : t.temperature_changes.back())
        << '\n'
        << "thermal_contraction = " << t.contraction << '\n'
        << "thermal_modulus_factor_min = " << t.min_modulus_factor << '\n'
        << "thermal_modulus_factor_max = " << t.max_modulus_factor << '\n'
        << "constant_modulus_nip_width_2b_mm = " << t.constant_width << '\n'
        << "constant_modulus_rolling_resistance_N_per_mm = "
        << t.constant_rolling_resistance << '\n'
        << "constant_modulus_bond_temperature_degC = " << t.constant_bond
        << '\n'
        << "constant_modulus_surface_temperature_degC = " << t.constant_surface
        << '\n'
        << "constant_modulus_max_temperature_degC = " << t.constant_max << '\n'
        << "thermal_nip_width_change_percent = "
        << change(t.width, t.constant_width) << '\n'
        << "thermal_rolling_resistance_change_percent = "
        << change(n.rolling_resistance, t.constant_rolling_resistance) << '\n'
        << "thermal_max_temperature_change_K = "
        << n.max_temperature - t.constant_max << '\n'
        << "thermal_wall_time_s = " << t.seconds << '\n';
    return out.str();
  }
} // namespace rollnip
