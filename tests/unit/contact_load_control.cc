// Load and indentation control on the nip-fitted mesh never miss a target
// that the cover can carry (issue: "load control that never misses"). On
// the default geometry (Spengos run 30, Rbar = 76.2 mm), with Q1-P0 at
// level 1 and Q2-P1 at level 0:
//  - Mode = load sweeps 20 targets from 0.5 to 80 N/mm, Mode = indentation
//    15 targets from 0.1 to 3.5 mm; none may be refused;
//  - each result is checked against an independent nip-angle solve (its
//    own problem, its own sweep) at the theta0 the control found: P and u0
//    must agree to 1e-5 (the default control tolerance is 1e-6, the
//    conformity tolerance here 1e-8);
//  - the median number of contact solves per target is printed and must
//    be at most 3 (a count, not a time);
//  - solves at a theta0 far from the target stop early (provisional):
//    each sweep must have some, and no answer may be one, so the check
//    against the nip-angle solves above covers them.
// A target beyond the mesh's largest nip is refused with the largest load
// reached named in the message.

#include <rollnip/contact/inverse_contact.h>
#include <rollnip/contact/nip_control.h>
#include <rollnip/problem.h>

#include "test_tools.h"

#include <algorithm>
#include <vector>

using namespace rollnip;

namespace
{
  Parameters::AllParameters
  scene(const std::string &element,
        const unsigned int level,
        const std::string &mode)
  {
    return testing::parameters_from_string(
      "subsection Geometry\n set Inner radius = 47.2\n"
      " set Outer radius = 60.7\n set Sector angle = 90\nend\n"
      "subsection Mesh\n set Radial cells = 6\n set Circumferential cells = "
      "24\n set Global refinements = " +
      std::to_string(level) +
      "\nend\n"
      "subsection Discretization\n set Element = " +
      element +
      "\nend\n"
      "subsection Contact\n set Mode = " +
      mode +
      "\n set Values = 1\n set Indenter radius = 76.2\n"
      " set Conformity tolerance = 1e-8\nend\n");
  }

  std::vector<double>
  geometric(const double from, const double to, const unsigned int n)
  {
    std::vector<double> v;
    for (unsigned int i = 0; i < n; ++i)
      v.push_back(from * std::pow(to / from, double(i) / (n - 1)));
    return v;
  }

  /// Runs the sweep under control and checks it against nip-angle solves.
  void
  check_sweep(testing::Checker          &checker,
              const std::string         &element,
              const unsigned int         level,
              const std::string         &mode,
              const std::vector<double> &targets)
  {
    const auto  p = scene(element, level, mode);
    RollProblem problem(p, MPI_COMM_WORLD);
    problem.setup();
    InverseContact contact(problem, p);
    NipControl     control(contact, p);

    const auto  pa = scene(element, level, "nip angle");
    RollProblem reference(pa, MPI_COMM_WORLD);
    reference.setup();
    InverseContact by_angle(reference, pa);

    unsigned int              refused = 0, provisional_answers = 0;
    double                    worst = 0;
    std::vector<unsigned int> solves;
    for (const double target : targets)
      {
        const unsigned int  before = control.n_contact_solves();
        const ContactResult r      = control.solve(target);
        solves.push_back(control.n_contact_solves() - before);
        provisional_answers += r.provisional;
        if (!r.converged)
          {
            ++refused;
            std::cout << "  refused: " << r.message << std::endl;
            continue;
          }
        const ContactResult a = by_angle.solve(r.theta0);
        worst                 = std::max({worst,
                                          std::abs(a.nip_load / r.nip_load - 1),
                                          std::abs(a.indentation / r.indentation - 1)});
        std::cout << "  " << mode << " " << target
                  << " -> theta0 = " << r.theta0 * 180 / numbers::PI
                  << " deg, P = " << r.nip_load
                  << " N/mm, u0 = " << r.indentation << " mm, " << solves.back()
                  << " contact solves" << std::endl;
      }
    std::vector<unsigned int> sorted = solves;
    std::sort(sorted.begin(), sorted.end());
    const unsigned int median = sorted[sorted.size() / 2];
    const std::string  what   = element + " level " + std::to_string(level) +
                             ", " + mode + ", " +
                             std::to_string(targets.size()) + " targets";
    checker.check(refused == 0,
                  what + ": none refused (" + std::to_string(refused) + ")");
    checker.check(worst < 1e-5,
                  what + ": nip-angle solves at the theta0 found agree to " +
                    testing::num(worst) + " < 1e-5");
    checker.check(control.n_provisional_solves() > 0 &&
                    provisional_answers == 0,
                  what + ": " + std::to_string(control.n_provisional_solves()) +
                    " provisional contact solves (> 0), none an answer (" +
                    std::to_string(provisional_answers) + ")");
    checker.check(median <= 3,
                  what + ": median contact solves per target " +
                    std::to_string(median) + " <= 3");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  const auto                       loads        = geometric(0.5, 80, 20);
  const auto                       indentations = geometric(0.1, 3.5, 15);

  check_sweep(checker, "Q1-P0", 1, "load", loads);
  check_sweep(checker, "Q1-P0", 1, "indentation", indentations);
  check_sweep(checker, "Q2-P1", 0, "load", loads);
  check_sweep(checker, "Q2-P1", 0, "indentation", indentations);

  // Beyond the largest nip of the mesh (theta0 = 45 deg): refused, and
  // the message says how far the cover went.
  const auto  p = scene("Q1-P0", 0, "load");
  RollProblem problem(p, MPI_COMM_WORLD);
  problem.setup();
  InverseContact      contact(problem, p);
  const ContactResult r = solve_controlled_nip(contact, p, 1e5);
  checker.check(!r.converged &&
                  r.message.find("out of reach") != std::string::npos &&
                  r.message.find("largest P reached") != std::string::npos,
                "P = 1e5 N/mm is refused: " + r.message);
  return checker.result();
}
