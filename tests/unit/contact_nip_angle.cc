// Batra's inverse contact iteration (doc/intro.md section 7) on the run-30
// geometry with the paper's indenter (Rbar = 76.2 mm): for two nip widths
// the conditions of a solved nip hold to the set tolerance (conformity of
// the whole zone, no penetration outside it, f >= 0), the load grows with
// the nip, and P converges under mesh refinement.

#include <rollnip/contact/inverse_contact.h>

#include "test_tools.h"

using namespace rollnip;

namespace
{
  ContactResult
  solve(const double theta0_deg, const unsigned int refinements)
  {
    const auto parameters = testing::parameters_from_string(
      "subsection Mesh\n set Radial cells = 6\n set Circumferential cells = "
      "24\n"
      " set Circumferential grading = 10\n set Global refinements = " +
      std::to_string(refinements) +
      "\nend\n"
      "subsection Contact\n set Mode = nip angle\n"
      " set Indenter radius = 76.2\n set Values = " +
      testing::num(theta0_deg) + "\n set Conformity tolerance = 1e-5\nend\n");
    RollProblem problem(parameters, MPI_COMM_WORLD);
    problem.setup();
    InverseContact contact(problem, parameters);
    return contact.solve(parameters.contact.values[0]);
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
      checker.check(r.conformity < 1e-5,
                    at + "conformity max |gap|/u0 = " +
                      testing::num(r.conformity) + " < 1e-5");
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

  // Refinement of P at theta0 = 8 deg: levels 1, 2, 3 (level 0 has about
  // 7 surface nodes in the zone; the whole sequence 0..4 is 10.560,
  // 10.268, 10.545, 10.582, 10.572 N/mm, not yet monotone: see issue 3).
  std::vector<double> P;
  for (const unsigned int level : {1u, 2u, 3u})
    P.push_back(solve(8., level).nip_load);
  const double d1 = std::abs(P[1] - P[0]), d2 = std::abs(P[2] - P[1]);
  std::cout << "  P at levels 1, 2, 3: " << P[0] << ", " << P[1] << ", " << P[2]
            << " N/mm" << std::endl;
  // No order is claimed (the error is not monotone: it depends on where
  // theta0 falls between two surface nodes); the successive differences
  // must contract.
  checker.check(d2 < 0.5 * d1,
                "successive differences of P contract: " + testing::num(d1) +
                  " -> " + testing::num(d2) + " N/mm (ratio < 0.5)");
  return checker.result();
}
