// The cover's steady temperature (doc/rolling.md, section 4) against the
// closed forms of an annulus R1 < r < R0 with a uniform source s and
// conductivity k, -k (r T')' / r = s:
//  A. core held at T_c, surface insulated:
//     T(r) = T_c - s (r^2 - R1^2) / (4 k) + s R0^2 / (2 k) ln(r / R1);
//  B. core insulated, surface cooled, -k T'(R0) = h (T(R0) - T_air):
//     T(R0) = T_air + s (R0^2 - R1^2) / (2 R0 h),
//     T(r)  = T(R0) + s (R0^2 - r^2) / (4 k) - s R1^2 / (2 k) ln(R0 / r).
//  C. core held at T_c, surface cooled: T(r) = T_c - s (r^2 - R1^2) / (4 k)
//     + c / k ln(r / R1), c = (s R0 / 2 - h (T_c - T_air)
//     + h s (R0^2 - R1^2) / (4 k)) / (1 / R0 + h / k ln(R0 / R1)).
// On the builtin sector mesh (its edges insulated), Q1 and Q2, the bond
// and surface temperatures converge to these at second order or better,
// and the heat balance (made = to the air + into the core) holds to 1e-6.

#include <rollnip/rolling/cover_temperature.h>

#include "test_tools.h"

using namespace rollnip;

namespace
{
  constexpr double R1 = 47.2e-3, R0 = 60.7e-3; // [m]
  constexpr double s = 2e5, k = 0.25, h = 40, T_air = 20, T_core = 30;

  double
  case_a(const double r)
  {
    return T_core - s * (r * r - R1 * R1) / (4 * k) +
           s * R0 * R0 / (2 * k) * std::log(r / R1);
  }

  double
  case_b(const double r)
  {
    const double T0 = T_air + s * (R0 * R0 - R1 * R1) / (2 * R0 * h);
    return T0 + s * (R0 * R0 - r * r) / (4 * k) -
           s * R1 * R1 / (2 * k) * std::log(R0 / r);
  }

  double
  case_c(const double r)
  {
    const double c = (s * R0 / 2 - h * (T_core - T_air) +
                      h * s * (R0 * R0 - R1 * R1) / (4 * k)) /
                     (1 / R0 + h / k * std::log(R0 / R1));
    return T_core - s * (r * r - R1 * R1) / (4 * k) + c / k * std::log(r / R1);
  }

  enum class Case
  {
    A,
    B,
    C
  };

  /// The errors [K] of the bond and surface temperatures for @p element
  /// at @p level, core @p insulated or not; checks the heat balance.
  std::string
  name(const Case which)
  {
    return which == Case::A ? " (A)" : which == Case::B ? " (B)" : " (C)";
  }

  std::array<double, 2>
  errors(const std::string &element,
         const unsigned int level,
         const Case         which,
         testing::Checker  &checker)
  {
    const bool insulated_core = which == Case::B;
    const auto parameters     = testing::parameters_from_string(
      "subsection Geometry\n set Inner radius = 47.2\n set Outer radius = "
          "60.7\nend\nsubsection Discretization\n set Element = " +
      element + "\nend\nsubsection Mesh\n set Global refinements = " +
      std::to_string(level) + "\nend\n");
    RollProblem problem(parameters, MPI_COMM_WORLD);
    problem.setup();
    Parameters::Rolling rolling;
    rolling.conductivity  = {k};
    rolling.heat_transfer = which == Case::A ? 0. : h;
    rolling.ambient       = T_air;
    rolling.core          = T_core;
    rolling.core_condition =
      insulated_core ? Parameters::CoreThermalCondition::insulated
                     : Parameters::CoreThermalCondition::fixed_temperature;
    CoverTemperature temperature(problem.body().mesh(),
                                 problem.body().mapping(),
                                 problem.body().fe().degree,
                                 parameters.geometry.sector_angle);
    const auto       r = temperature.solve([](double) { return s; }, rolling);
    const auto       exact = which == Case::A   ? case_a
                             : which == Case::B ? case_b
                                                : case_c;
    const double     made  = s * numbers::PI * (R0 * R0 - R1 * R1); // [W/m]
    const double     imbalance =
      std::abs(r.generated - r.to_air - r.to_core) / r.generated;
    const std::string at =
      element + " level " + std::to_string(level) + name(which) + ": ";
    checker.check(imbalance < 1e-6,
                  at + "heat made " + testing::num(r.generated) +
                    " W/m = to air " + testing::num(r.to_air) + " + to core " +
                    testing::num(r.to_core) + ", imbalance " +
                    testing::num(imbalance));
    checker.check(std::abs(r.generated / made - 1) < 2e-2,
                  at + "heat made over s pi (R0^2 - R1^2) = " +
                    testing::num(r.generated / made));
    std::cout << "  " << at << "T bond " << r.bond << " (exact " << exact(R1)
              << "), T surface " << r.surface << " (exact " << exact(R0)
              << "), T max " << r.max << " degC" << std::endl;
    return {{std::abs(r.bond - exact(R1)), std::abs(r.surface - exact(R0))}};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  for (const Case which : {Case::A, Case::B, Case::C})
    for (const std::string element : {"Q1-P0", "Q2-P1"})
      {
        std::vector<std::array<double, 2>> e;
        for (unsigned int level = 0; level <= 2; ++level)
          e.push_back(errors(element, level, which, checker));
        // The temperature that is not held: the bond (B) or surface.
        const unsigned int free = which == Case::B ? 0 : 1;
        const double rise = std::abs(which == Case::A   ? case_a(R0) - T_core
                                     : which == Case::B ? case_b(R1) - T_air
                                                        : case_c(R0) - T_core);
        const double p    = testing::order(e[1][free], e[2][free]);
        checker.check(p > 1.8 && e[2][free] < 1e-3 * rise,
                      element + name(which) +
                        ": error of the free end's temperature " +
                        testing::num(e[1][free]) + " -> " +
                        testing::num(e[2][free]) + " K, order " +
                        testing::num(p) + ", below 0.1 % of the rise " +
                        testing::num(rise) + " K");
      }
  return checker.result();
}
