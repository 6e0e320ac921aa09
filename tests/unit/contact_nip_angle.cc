// Batra's inverse contact iteration (doc/intro.md section 7) on the run-30
// geometry with the paper's indenter (Rbar = 76.2 mm): for two nip widths
// the conditions of a solved nip hold to the set tolerance (conformity of
// the whole zone, no penetration outside it, f >= 0), the load grows with
// the nip, and P converges under mesh refinement at an observed order
// (at a fixed theta0 and at a fixed P, for Q1-P0 and Q2-P1).

#include <rollnip/contact/nip_control.h>

#include "test_tools.h"

using namespace rollnip;

namespace
{
  std::string
  precise(const double x)
  {
    std::ostringstream s;
    s << std::setprecision(15) << x;
    return s.str();
  }

  /// The nip at @p value: theta0 [deg] for Mode = nip angle, else P.
  ContactResult
  solve(const double       value,
        const unsigned int refinements,
        const std::string &element = "Q1-P0",
        const std::string &mode    = "nip angle")
  {
    const auto parameters = testing::parameters_from_string(
      "subsection Mesh\n set Radial cells = 6\n set Circumferential cells = "
      "24\n"
      " set Circumferential grading = 10\n set Global refinements = " +
      std::to_string(refinements) +
      "\nend\nsubsection Discretization\n set Element = " + element +
      "\nend\n"
      "subsection Contact\n set Mode = " +
      mode + "\n set Indenter radius = 76.2\n set Values = " + precise(value) +
      "\n set Conformity tolerance = 1e-8\n set Control tolerance = "
      "1e-9\nend\n");
    RollProblem problem(parameters, MPI_COMM_WORLD);
    problem.setup();
    InverseContact contact(problem, parameters);
    return solve_controlled_nip(contact,
                                parameters,
                                parameters.contact.values[0]);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  std::vector<double>              loads;
  for (const double theta0 : {5., 8.})
    {
      const ContactResult r  = solve(theta0, 1);
      const std::string   at = "theta0 = " + testing::num(theta0) + " deg: ";
      checker.check(r.converged,
                    at + "converged in " + std::to_string(r.iterations) +
                      " iterations " + r.message);
      checker.check(r.conformity < 1e-8,
                    at + "conformity max |gap|/u0 = " +
                      testing::num(r.conformity) + " < 1e-8");
      checker.check(r.penetration <= 1e-5,
                    at + "penetration outside / u0 = " +
                      testing::num(r.penetration));
      checker.check(r.min_pressure >= 0,
                    at + "min f = " + testing::num(r.min_pressure) +
                      " MPa >= 0");
      std::cout << "  " << at << "P = " << r.nip_load
                << " N/mm, u0 = " << r.indentation
                << " mm, peak f = " << r.peak_pressure << " MPa" << std::endl;
      loads.push_back(r.nip_load);
    }
  checker.check(loads[1] > loads[0],
                "P grows with the nip: " + testing::num(loads[0]) + " -> " +
                  testing::num(loads[1]) + " N/mm");

  // Refinement on the nip-fitted mesh, where the contact edge is a node
  // at every theta0: P at a fixed theta0 (7.3711 deg) and theta0 at a
  // fixed P (8.4 N/mm, the same nip) converge monotonically, Q1-P0 at an
  // observed order between 1 and 2.5; Q2-P1 monotonically too.
  for (const std::string element : {"Q1-P0", "Q2-P1"})
    for (const std::string mode : {"nip angle", "load"})
      {
        const bool          by_angle = mode == "nip angle";
        std::vector<double> v;
        const unsigned int  n_levels = element == "Q1-P0" ? 4 : 3;
        for (unsigned int level = 0; level < n_levels; ++level)
          {
            const ContactResult r =
              solve(by_angle ? 7.3711 : 8.4, level, element, mode);
            v.push_back(by_angle ? r.nip_load : r.theta0 * 180 / numbers::PI);
            std::cout << "  " << element << ", " << mode << ", level " << level
                      << ": " << (by_angle ? "P = " : "theta0 = ") << v.back()
                      << (by_angle ? " N/mm" : " deg") << std::endl;
          }
        const std::string what =
          element + ", " +
          (by_angle ? "P at theta0 = 7.3711 deg" : "theta0 at P = 8.4 N/mm");
        bool monotone = true;
        for (std::size_t k = 2; k < v.size(); ++k)
          monotone = monotone && (v[k] - v[k - 1]) * (v[1] - v[0]) > 0 &&
                     std::abs(v[k] - v[k - 1]) < std::abs(v[k - 1] - v[k - 2]);
        checker.check(monotone, what + ": monotone, differences shrinking");
        if (v.size() == 4)
          {
            const double p1 = testing::order(v[1] - v[0], v[2] - v[1]),
                         p2 = testing::order(v[2] - v[1], v[3] - v[2]);
            // Measured on the default nip-fitted mesh: 2.4 then 1.96
            // for P at theta0 = 7.3711 deg.
            checker.check(p1 > 0.8 && p1 < 2.6 && p2 > 0.8 && p2 < 2.2,
                          what + ": observed orders " + testing::num(p1) +
                            " in [0.8, 2.6], " + testing::num(p2) +
                            " in [0.8, 2.2]");
          }
      }
  return checker.result();
}
