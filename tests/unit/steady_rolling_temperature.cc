// The cover's temperature under the full steady rolling's heat source
// (doc/rolling.md, section 7) against independent truth:
// - on the full rolling's whole-circle mesh, a uniform source with the
//   core insulated and the surface cooled gives the closed form of an
//   annulus (tests/unit/cover_temperature.cc, case B), and with the core
//   held (case C) on a coarse mesh of a larger roll;
// - the heat made is the full route's dissipated power (the source's
//   circles are the rings' radial Gauss points: exact to round-off), and
//   it leaves through the surface and the core to 1e-6;
// - at small V tau / b the full route's temperature rises (over the
//   field without a source) are the first-order route's, as closely as
//   the two losses agree;
// - at V tau / b = 1, far beyond first order, with the core insulated the
//   mean surface temperature rises by exactly Q / (h L) over the air,
//   Q = F_r V the full route's heat and L the surface's length, whatever
//   the source's radial profile (2 pi R0 on a round roll; the mesh's
//   polygon is slightly shorter), so the full and first-order rises are
//   in the ratio of their F_r.

#include <rollnip/rolling/steady_rolling.h>
#include <rollnip/rolling/steady_rolling_sweep.h>
#include <rollnip/rolling/steady_rolling_temperature.h>

#include "steady_rolling_scene.h"
#include "test_tools.h"

using namespace rollnip;

namespace
{
  constexpr double R0 = testing::rolling_R0, R1 = testing::rolling_R1;
  constexpr double g = testing::rolling_g, tau = testing::rolling_tau;
  constexpr double k = 0.25, h = 30, T_air = 20, T_core = 35;

  /// The thermal data, the core held at @p core [degC] or insulated.
  Parameters::Rolling
  thermal(const bool insulated_core, const double core = T_core)
  {
    Parameters::Rolling r;
    r.layers         = {{{g}, {tau}}};
    r.conductivity   = {k};
    r.heat_transfer  = h;
    r.ambient        = T_air;
    r.core           = core;
    r.core_condition = insulated_core
                         ? Parameters::CoreThermalCondition::insulated
                         : Parameters::CoreThermalCondition::fixed_temperature;
    return r;
  }

  /// The surface's length on the mesh [mm]: the polygon of its nodes.
  double
  surface_length(const AnnulusMesh &annulus)
  {
    const auto  &a = annulus.angles();
    double       L = 0;
    const double n = a.size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const double next = i + 1 < n ? a[i + 1] : a[0] + 2 * numbers::PI;
        L += 2 * R0 * std::sin(0.5 * (next - a[i]));
      }
    return L;
  }

  /// A uniform source s [W/m^3] on the whole-circle mesh, core insulated,
  /// against the closed form of the annulus.
  void
  check_uniform_source(testing::Checker              &checker,
                       SteadyRollingTemperature      &heat,
                       const std::vector<CircleLoss> &shape)
  {
    constexpr double        s = 2e5, r1 = R1 * 1e-3, r0 = R0 * 1e-3; // SI
    std::vector<CircleLoss> uniform = shape;
    for (auto &c : uniform)
      c.mean = s;
    const auto   T  = heat.solve(uniform, thermal(true));
    const double Ts = T_air + s * (r0 * r0 - r1 * r1) / (2 * r0 * h);
    const double Tb = Ts + s * (r0 * r0 - r1 * r1) / (4 * k) -
                      s * r1 * r1 / (2 * k) * std::log(r0 / r1);
    checker.check(std::abs(T.bond - Tb) < 2e-3 * (Tb - T_air),
                  "uniform source, insulated core: T bond " +
                    testing::num(T.bond) + " degC, closed form " +
                    testing::num(Tb) + " (within 0.2 % of the rise)");
  }

  /// A uniform source s [W/m^3] with the core held at T_core and the
  /// surface cooled, on a whole-circle mesh of a 250 mm roll with few and
  /// long cells along the circle (where a surface face's centre lies
  /// deeper than the outermost ring is thick), against the closed form
  /// of the annulus (tests/unit/cover_temperature.cc, case C).
  void
  check_coarse_annulus(testing::Checker &checker)
  {
    constexpr double s = 2e4, r1 = 0.1115, r0 = 0.125; // SI
    AnnulusLayout    layout;
    layout.layer_radii     = {1e3 * r1, 1e3 * r0};
    layout.fine_half_angle = 0.1;
    layout.fine_cells      = 4;
    layout.growth          = 1.5;
    layout.radial_cells    = 16;
    layout.radial_grading  = 0.3;
    const AnnulusMesh        annulus(layout);
    SteadyRollingTemperature heat(annulus);
    std::vector<CircleLoss>  uniform;
    const auto              &radii = annulus.radii();
    for (unsigned int j = 0; j + 1 < radii.size(); ++j)
      for (const double xi : {0.5 - std::sqrt(3.) / 6, 0.5 + std::sqrt(3.) / 6})
        uniform.push_back(
          {radii[j] + xi * (radii[j + 1] - radii[j]), 0, 0, s, 0});
    const auto   T = heat.solve(uniform, thermal(false));
    const double c = (s * r0 / 2 - h * (T_core - T_air) +
                      h * s * (r0 * r0 - r1 * r1) / (4 * k)) /
                     (1 / r0 + h / k * std::log(r0 / r1));
    const double Ts =
      T_core - s * (r0 * r0 - r1 * r1) / (4 * k) + c / k * std::log(r0 / r1);
    checker.check(std::abs(T.surface - Ts) < 1e-2 * std::abs(Ts - T_air),
                  "uniform source, core 35 degC, coarse circle: T surface " +
                    testing::num(T.surface) + " degC, closed form " +
                    testing::num(Ts) +
                    " (within 1 % of its rise over the "
                    "air)");
  }

  /// Heat made = the full route's power, and = heat leaving.
  void
  check_balance(testing::Checker             &checker,
                const CoverTemperatureResult &T,
                const double                  power,
                const std::string            &at)
  {
    checker.check(std::abs(T.generated / power - 1) < 1e-9,
                  at + ": heat made " + testing::num(T.generated) +
                    " W/m = the full route's dissipation " +
                    testing::num(power) + " (to 1e-9)");
    checker.check(std::abs(T.generated - T.to_air - T.to_core) <
                    1e-6 * T.generated,
                  at + ": heat made = to air " + testing::num(T.to_air) +
                    " + to core " + testing::num(T.to_core) + " (to 1e-6)");
  }

  /// At small V tau / b: the rises of the temperatures that are not held
  /// (over the air's, which they are without a source) in the ratio of
  /// the full and first-order losses, and the heat balance.
  void
  check_low_speed(testing::Checker         &checker,
                  SteadyRollingTemperature &heat,
                  const SteadyRolling      &rolling,
                  const RollingLoss        &first,
                  const bool                insulated,
                  const std::string        &at)
  {
    const auto   data = thermal(insulated, T_air);
    const auto   r    = rolling.result();
    const auto   T    = heat.solve(rolling.heat_source(), data);
    const auto   T1   = heat.solve(first.circles, data);
    const double loss = r.resistance_energy / first.rolling_resistance;
    check_balance(checker, T, r.power, at);
    using Rise = std::tuple<std::string, double, double>;
    std::vector<Rise> rises{{"surface", T.surface, T1.surface},
                            {"max", T.max, T1.max}};
    if (insulated)
      rises.emplace_back("bond", T.bond, T1.bond);
    for (const auto &[name, full, fo] : rises)
      {
        const double rise = (full - T_air) / (fo - T_air);
        checker.check(
          std::abs(rise - loss) < 0.005 && std::abs(rise - 1) < 0.03,
          at + ": " + name + " temperature rise full / first order " +
            testing::num(rise) + ", F_r full / first order " +
            testing::num(loss) + " (within 0.005; both within 3 % of 1)");
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  const double                     theta0 = 3 * numbers::PI / 180;
  const auto          parameters          = testing::rolling_nip_parameters(2);
  const ContactResult nip = testing::symmetric_nip(parameters, theta0);
  checker.check(nip.converged, "symmetric nip converged");

  SteadyRolling rolling(
    testing::steady_rolling_scene(parameters.material, theta0));
  checker.check(rolling.solve_elastic(nip.indentation, 2),
                "whole-circle elastic nip converged");
  const auto               circles = rolling.circles();
  const double             b       = rolling.result().half_width;
  SteadyRollingTemperature heat(rolling.annulus());
  check_uniform_source(checker, heat, rolling.heat_source());
  check_coarse_annulus(checker);

  for (const double ratio : {0.003, 0.01, 0.1, 0.3, 1.})
    {
      const double V = ratio * b / tau * 1e-3; // [m/s]
      checker.check(rolling.solve_speed(V),
                    "converged at V tau / b = " + testing::num(ratio));
      const auto r     = rolling.result();
      const auto first = first_order_whole_turn(circles, thermal(false), R0, V);
      const std::string at = "V tau / b = " + testing::num(ratio);
      if (ratio <= 0.01)
        for (const bool insulated : {false, true})
          check_low_speed(checker,
                          heat,
                          rolling,
                          first,
                          insulated,
                          at + (insulated ? ", insulated core"
                                          : ", core at the air's 20 degC"));
      if (ratio == 1.)
        {
          const auto   T  = heat.solve(rolling.heat_source(), thermal(true));
          const auto   T1 = heat.solve(first.circles, thermal(true));
          const double Q  = r.resistance_energy * 1e3 * V; // [W/m]
          const double L  = surface_length(rolling.annulus());
          check_balance(checker, T, r.power, at + ", insulated core");
          const double rise = (T.surface - T_air) * h * L * 1e-3 / Q;
          checker.check(std::abs(rise - 1) < 1e-6,
                        at +
                          ": mean surface rise (T - T_air) h L / (F_r "
                          "V) = " +
                          testing::num(rise) +
                          " (1 to 1e-6); with 2 pi R0 "
                          "for L: 1 + " +
                          testing::num(rise * 2 * numbers::PI * R0 / L - 1));
          const double fo   = (T.surface - T_air) / (T1.surface - T_air);
          const double loss = r.resistance_energy / first.rolling_resistance;
          checker.check(std::abs(fo / loss - 1) < 1e-6,
                        at + ": surface rise full / first order " +
                          testing::num(fo) + " = F_r ratio " +
                          testing::num(loss) + " (to 1e-6)");
          std::cout << "  " << at << ": T bond " << T.bond << " degC (first "
                    << "order " << T1.bond << "), T max " << T.max
                    << " (first order " << T1.max << ")" << std::endl;
        }
    }
  return checker.result();
}
