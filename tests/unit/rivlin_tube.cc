// Exact solution 2 of doc/intro.md section 8: the plane-strain Rivlin tube.
// A quarter tube (R1 = 47.2, R0 = 60.7 mm) inflated by a follower pressure q
// on the inner arc, outer arc free, both edges symmetric. With r^2 = R^2 + c
// the exact inflation satisfies
//   q = (C1 + C2) [G(b^2) - G(a^2)],  G(x) = ln((x - c)/x) - c/x,
// a^2 = R1^2 + c, b^2 = R0^2 + c, and q < 2 (C1 + C2) ln(R0/R1) always.
// We compare the inner and outer radius changes over pressures up to 80 %
// of that limit at three refinements and assert the observed order.

#include "test_tools.h"

using namespace rollnip;

namespace
{
  constexpr double R1 = 47.2, R0 = 60.7, C = 0.5; // C = C1 + C2 [MPa]

  double
  pressure_of_c(const double c)
  {
    auto G = [c](const double x) { return std::log((x - c) / x) - c / x; };
    return C * (G(R0 * R0 + c) - G(R1 * R1 + c));
  }

  /// c for a given q (q(c) is increasing).
  double
  c_of_pressure(const double q)
  {
    return testing::increasing_root(pressure_of_c, q);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  const double                     limit = 2 * C * std::log(R0 / R1);
  std::cout << "ballooning limit 2 (C1 + C2) ln(R0/R1) = " << limit << " MPa"
            << std::endl;

  const std::vector<double> fractions = {0.2, 0.4, 0.6, 0.8};
  // errors[level] = max over pressures of the relative error in (a - R1)
  // and (b - R0).
  std::vector<double> errors;
  for (const unsigned int refinements : {1u, 2u, 3u})
    {
      double worst = 0;
      for (const double fraction : fractions)
        {
          const double q          = fraction * limit;
          const auto   parameters = testing::parameters_from_string(
            "subsection Mesh\n"
              " set Radial cells = 2\n set Circumferential cells = 4\n"
              " set Circumferential grading = 1\n"
              " set Global refinements = " +
            std::to_string(refinements) +
            "\nend\n"
              "subsection Material\n set C1 = 0.3\n set C2 = 0.2\nend\n"
              "subsection Boundary conditions\n"
              " set Inner arc (id 0) = pressure\n set Outer arc (id 1) = free\n"
              " set Symmetry edge (id 2) = symmetry\n"
              " set Far edge (id 3) = symmetry\nend\n"
              "subsection Load\n set Pressure function = p0\n set p0 = " +
            testing::num(q) + "\nend\n");
          RollProblem problem(parameters, MPI_COMM_WORLD);
          problem.setup();
          const RunStatus status = problem.run();
          checker.check(status.converged,
                        "converged at q = " + testing::num(q) + " MPa");
          const double c = c_of_pressure(
            parameters.load.p0); // the pressure as parsed (4 digits)
          const double exact_a = std::sqrt(R1 * R1 + c) - R1;
          const double exact_b = std::sqrt(R0 * R0 + c) - R0;
          const double fe_a = problem.radial_displacement_at(Point<dim>(R1, 0));
          const double fe_b = problem.radial_displacement_at(Point<dim>(R0, 0));
          const double e    = std::max(std::abs(fe_a - exact_a) / exact_a,
                                    std::abs(fe_b - exact_b) / exact_b);
          std::cout << std::defaultfloat << std::setprecision(6) << "  level "
                    << refinements << "  q = " << std::setw(8)
                    << parameters.load.p0 << " MPa  a-R1: FE " << fe_a
                    << " exact " << exact_a << "   b-R0: FE " << fe_b
                    << " exact " << exact_b << "   rel. error " << e
                    << "  (hoop stretch at R1: " << (R1 + exact_a) / R1 << ")"
                    << std::endl;
          worst = std::max(worst, e);
        }
      errors.push_back(worst);
    }
  for (unsigned int l = 1; l < errors.size(); ++l)
    {
      const double p = testing::order(errors[l - 1], errors[l]);
      // Q1 on a polygonal approximation of the circles: second order.
      checker.check(p > 1.7 && p < 2.5,
                    "observed order " + testing::num(p) +
                      " of the radius changes in [1.7, 2.5] (level " +
                      std::to_string(l) + " -> " + std::to_string(l + 1) + ")");
    }
  checker.check(errors.back() < 2e-3,
                "finest relative error " + testing::num(errors.back()) +
                  " < 2e-3");
  return checker.result();
}
