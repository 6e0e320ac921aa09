// The load- and indentation-controlled nips invert the nip-angle-controlled
// one (doc/intro.md, section 7): the P (or u0) found at theta0 = 7 deg,
// prescribed, gives back theta0 = 7 deg to the outer tolerance. And a flat
// indenter (Rbar = infinity: two equal covered rolls) solves with the same
// conformity, no penetration and f >= 0, and needs less load than the
// Rbar = 76.2 mm cylinder for the same nip (its relative curvature is
// smaller: 1/R0 instead of 1/R0 + 1/Rbar).

#include <rollnip/contact/inverse_contact.h>
#include <rollnip/contact/nip_control.h>
#include <rollnip/problem.h>

#include "test_tools.h"

using namespace rollnip;

namespace
{
  Parameters::AllParameters
  scene(const std::string &mode, const std::string &radius)
  {
    return testing::parameters_from_string(
      "subsection Mesh\n set Radial cells = 6\n set Circumferential cells = "
      "24\n"
      " set Circumferential grading = 10\n set Global refinements = 1\nend\n"
      "subsection Contact\n set Mode = " +
      mode + "\n set Indenter radius = " + radius +
      "\n set Conformity tolerance = 1e-8\n set Control tolerance = 1e-8\n"
      "end\n");
  }

  ContactResult
  solve(const Parameters::AllParameters &p, const double target)
  {
    RollProblem problem(p, MPI_COMM_WORLD);
    problem.setup();
    InverseContact contact(problem, p);
    return solve_controlled_nip(contact, p, target);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  const double                     theta0 = 7 * numbers::PI / 180;

  const ContactResult by_angle = solve(scene("nip angle", "76.2"), theta0);
  checker.check(by_angle.converged,
                "theta0 = 7 deg: P = " + testing::num(by_angle.nip_load) +
                  " N/mm, u0 = " + testing::num(by_angle.indentation) + " mm");
  for (const std::string mode : {"load", "indentation"})
    {
      const double target =
        mode == "load" ? by_angle.nip_load : by_angle.indentation;
      const ContactResult r = solve(scene(mode, "76.2"), target);
      const double        e = std::abs(r.theta0 / theta0 - 1);
      checker.check(r.converged && e < 1e-6,
                    mode + " " + testing::num(target) + " gives theta0 = " +
                      testing::num(r.theta0 * 180 / numbers::PI) +
                      " deg (relative difference " + testing::num(e) +
                      " < 1e-6)");
    }

  const ContactResult flat = solve(scene("nip angle", "inf"), theta0);
  checker.check(flat.converged && flat.conformity < 1e-8 &&
                  flat.penetration == 0 && flat.min_pressure >= 0,
                "flat indenter: conformity " + testing::num(flat.conformity) +
                  ", penetration " + testing::num(flat.penetration) +
                  ", min f " + testing::num(flat.min_pressure) + " MPa");
  checker.check(flat.nip_load < by_angle.nip_load,
                "flat plane needs less load for the same nip: " +
                  testing::num(flat.nip_load) + " < " +
                  testing::num(by_angle.nip_load) + " N/mm");
  return checker.result();
}
