// Linear theory of a thin two-layer cover against its lubrication asymptote
// (doc/layers.md). A bonded incompressible stack of thickness H on a rigid
// core, pressed by a frictionless cylinder, carries the pressure p(x) by a
// shear flow: with tau = p'(x) (z - H) (free of shear at the surface) the
// horizontal displacement is u(z) = p' int_0^z (s - H) / G(s) ds, and the
// indentation is the divergence of its flux,
//   delta(x) = -K p''(x),  K = int_0^H (H - s)^2 / G(s) ds,
// so that delta = u0 - x^2 / (2R) on |x| < a gives
//   P_thin = 2 a^5 / (45 R K),  u0_thin = a^2 / (6 R),
// (for one layer K = H^3 / (3G) and P_thin = 2 G a^5 / (15 R H^3)). Two
// equal halves with a top four times stiffer than the base (a stiff top
// coat), and the reverse (a hard base): P_FE / P_thin must approach 1 from
// above at first order in H/a (a/H = 8, 16, 32), as the one-layer cover
// does in contact_thin_layer, and land far from the one-layer formulas with
// either layer's modulus. Mesh: 2 cells through each layer, 160 uniform
// cells over the 15 deg sector, run-30 radii R0 = 60.7, Rbar = 76.2 mm.

#include <rollnip/contact/inverse_contact.h>

#include "test_tools.h"

using namespace rollnip;

namespace
{
  constexpr double R0 = 60.7, a = 4.;

  /// P_FE / P_thin - 1 at a/H = 8, 16, 32 for base and top moduli G1, G2
  /// (C1 = G/2, C2 = 0).
  std::vector<double>
  excess_over_asymptote(testing::Checker &checker,
                        const double      G1,
                        const double      G2)
  {
    const double        R      = 1. / (1. / R0 + 1. / 76.2);
    const double        theta0 = std::asin(a / R0);
    std::vector<double> excess;
    for (const double H : {0.5, 0.25, 0.125})
      {
        std::ostringstream prm;
        prm << std::setprecision(15) << "subsection Geometry\n"
            << " set Inner radius = " << R0 - H
            << "\n set Outer radius = 60.7\n set Sector angle = 15\nend\n"
            << "subsection Mesh\n set Radial cells = 4\n"
            << " set Circumferential cells = 160\n"
            << " set Circumferential grading = 1\n set Radial grading = 1\n"
            << " set Global refinements = 0\n set Nip fitting = off\nend\n"
            << "subsection Material\n set Theory = linear\n"
            << " set C1 = " << G1 / 2 << ", " << G2 / 2
            << "\n set C2 = 0, 0\n set Layer thicknesses = " << H / 2 << ", "
            << H / 2 << "\nend\n"
            << "subsection Contact\n set Mode = nip angle\n set Values = 3\n"
            << " set Indenter radius = 76.2\nend\n";
        const auto  p = testing::parameters_from_string(prm.str());
        RollProblem problem(p, MPI_COMM_WORLD);
        problem.setup();
        InverseContact      contact(problem, p);
        const ContactResult r = contact.solve(theta0);
        const double        t = H / 2;
        const double        K =
          (H * H * H - t * t * t) / (3 * G1) + t * t * t / (3 * G2);
        const double P_thin    = 2 * std::pow(a, 5) / (45 * R * K);
        const auto   one_layer = [&](const double G) {
          return 2 * G * std::pow(a, 5) / (15 * R * H * H * H);
        };
        const std::string at = "G1 = " + testing::num(G1) +
                               ", G2 = " + testing::num(G2) +
                               " MPa, a/H = " + testing::num(a / H) + ": ";
        checker.check(r.converged && r.conformity < 1e-6,
                      at + "converged, conformity " +
                        testing::num(r.conformity));
        excess.push_back(r.nip_load / P_thin - 1);
        std::cout << "  " << at << "P = " << r.nip_load
                  << " N/mm, P_thin(layered) = " << P_thin
                  << " N/mm, ratio = " << r.nip_load / P_thin
                  << "; one-layer formula with G1: " << one_layer(G1)
                  << ", with G2: " << one_layer(G2) << " N/mm" << std::endl;
      }
    return excess;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  for (const auto &moduli :
       std::vector<std::pair<double, double>>{{0.5, 2.}, {2., 0.5}})
    {
      const auto excess =
        excess_over_asymptote(checker, moduli.first, moduli.second);
      for (unsigned int i = 0; i < excess.size(); ++i)
        checker.check(excess[i] > 0,
                      "P_FE / P_thin = " + testing::num(1 + excess[i]) +
                        " lies above 1");
      for (unsigned int i = 1; i < excess.size(); ++i)
        {
          const double rate = excess[i - 1] / excess[i];
          checker.check(rate > 1.5 && rate < 3,
                        "halving H divides P_FE / P_thin - 1 by " +
                          testing::num(rate) +
                          " (first order in H/a: in [1.5, 3])");
        }
      // The remainder of a first-order extrapolation is second order in
      // H/a, about the square of the last excess (0.2 to 0.4): 0.12.
      const double limit = 1 + 2 * excess[2] - excess[1];
      checker.check(std::abs(limit - 1) < 0.12,
                    "extrapolated P_FE / P_thin at H/a = 0: " +
                      testing::num(limit) + " (within 0.12 of 1)");
    }
  return checker.result();
}
