// Linear theory against the thin bonded incompressible layer (doc/intro.md
// section 7): a cover of thickness h on the
// run-30 outer radius R0 = 60.7 mm, pressed by the Rbar = 76.2 mm cylinder
// over the half-width a = 4 mm, with a/h = 8, 16, 32. The lubrication-type
// asymptote of a frictionless indenter is
//   P_thin = 2 G a^5 / (15 R h^3),  u0_thin = a^2 / (6 R),
//   1/R = 1/R0 + 1/Rbar,
// and it is approached from above with a relative error of order h/a. So:
// P_FE / P_thin > 1, falling monotonically as h shrinks, its excess over 1
// roughly halving with h (first order in h/a), about 25 % left at a/h = 32;
// u0 falls towards a^2 / (6 R) likewise. Mesh: 4 cells through h and 160
// uniform cells over the 15 deg sector (about a/43 each); halving the
// circumferential cells changes the ratio by at most 3.5 % (a/h = 32).

#include <rollnip/contact/inverse_contact.h>

#include "test_tools.h"

using namespace rollnip;

// The uniform fixed mesh (Nip fitting = off): 40 cells across the zone
// resolve the thin layer's (a^2 - x^2)^2 pressure; the nip-fitted mesh
// would put Mesh/Nip cells there.
int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  const double                     R0 = 60.7, Rbar = 76.2, a = 4.;
  const double                     R      = 1. / (1. / R0 + 1. / Rbar);
  const double                     theta0 = std::asin(a / R0);
  std::vector<double>              excess, u0_excess;
  for (const double h : {0.5, 0.25, 0.125})
    {
      std::ostringstream inner;
      inner << std::setprecision(15) << R0 - h;
      const auto parameters = testing::parameters_from_string(
        "subsection Geometry\n set Inner radius = " + inner.str() +
        "\n set Outer radius = 60.7\n set Sector angle = 15\nend\n"
        "subsection Mesh\n set Radial cells = 4\n"
        " set Circumferential cells = 160\n set Circumferential grading = "
        "1\n set Global refinements = 0\n set Nip fitting = off\nend\n"
        "subsection Material\n set Theory = linear\nend\n"
        "subsection Contact\n set Mode = nip angle\n set Values = 3\n"
        " set Indenter radius = 76.2\nend\n");
      RollProblem problem(parameters, MPI_COMM_WORLD);
      problem.setup();
      InverseContact      contact(problem, parameters);
      const ContactResult r = contact.solve(theta0);
      if (!r.converged)
        std::cout << "  " << r.message << std::endl;
      const double      G       = 2 * (parameters.material.layer_C1.back() +
                            parameters.material.layer_C2.back());
      const double      P_thin  = 2 * G * std::pow(a, 5) / (15 * R * h * h * h);
      const double      u0_thin = a * a / (6 * R);
      const std::string at      = "a/h = " + testing::num(a / h) + ": ";
      checker.check(r.converged && r.conformity < 1e-6,
                    at + "converged, conformity " + testing::num(r.conformity));
      excess.push_back(r.nip_load / P_thin - 1);
      u0_excess.push_back(r.indentation / u0_thin - 1);
      std::cout << "  " << at << "P = " << r.nip_load
                << " N/mm, P_thin = " << P_thin
                << " N/mm, ratio = " << r.nip_load / P_thin
                << "; u0 = " << r.indentation << " mm, a^2/(6R) = " << u0_thin
                << " mm" << std::endl;
    }
  for (unsigned int i = 0; i < excess.size(); ++i)
    checker.check(excess[i] > 0 && u0_excess[i] > 0,
                  "P_FE / P_thin = " + testing::num(1 + excess[i]) +
                    " and u0 / u0_thin = " + testing::num(1 + u0_excess[i]) +
                    " lie above 1");
  for (unsigned int i = 1; i < excess.size(); ++i)
    {
      const double rate = excess[i - 1] / excess[i];
      checker.check(rate > 1.5 && rate < 3,
                    "halving h divides P_FE / P_thin - 1 by " +
                      testing::num(rate) +
                      " (first order in h/a: in [1.5, 3])");
      checker.check(u0_excess[i] < u0_excess[i - 1],
                    "u0 / u0_thin - 1 falls: " +
                      testing::num(u0_excess[i - 1]) + " -> " +
                      testing::num(u0_excess[i]));
    }
  checker.check(excess.back() > 0.15 && excess.back() < 0.45,
                "at a/h = 32 P lies " + testing::num(100 * excess.back()) +
                  " % above the asymptote (expected: about 25 %)");
  return checker.result();
}
