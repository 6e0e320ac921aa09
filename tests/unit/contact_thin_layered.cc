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
// equal halves with a top four times stiffer than the base, the reverse (a
// hard base), and a thin stiff top coat (a quarter of H, ten times the
// base's modulus): P_FE / P_thin must approach 1 from above at first order
// in H/a (a/H = 8, 16, 32), as the one-layer cover does in
// contact_thin_layer, and land far from the one-layer formulas with either
// layer's modulus. Against a single layer of the base material and the
// same total thickness, the top coat carries K_single / K_coat = 1.014
// times its load in the thin limit (the shear flow runs mostly near the
// core, where the coat is not): the ratio of the two FE loads, 1.67 at
// a/H = 8 (at finite a/H the stiff coat spreads the load), must fall
// towards that and, extrapolated to H/a = 0 at first order, land on it
// within the remainder of the extrapolation. Mesh: 4 cells
// through the cover, 160 uniform cells over the 15 deg sector, run-30
// radii R0 = 60.7, Rbar = 76.2 mm.

#include <rollnip/contact/inverse_contact.h>

#include "test_tools.h"

using namespace rollnip;

namespace
{
  constexpr double R0 = 60.7, a = 4.;

  constexpr double R_effective = 1. / (1. / R0 + 1. / 76.2);

  /// The FE loads at a/H = 8, 16, 32 of a cover whose base has shear
  /// modulus G1 and whose top @p top_fraction of the thickness has G2
  /// (C1 = G/2, C2 = 0), and their excess over the layered asymptote.
  struct Series
  {
    std::vector<double> load, excess;
  };

  Series
  thin_layered_series(testing::Checker &checker,
                      const double      G1,
                      const double      G2,
                      const double      top_fraction)
  {
    const double theta0 = std::asin(a / R0);
    Series       series;
    for (const double H : {0.5, 0.25, 0.125})
      {
        const double       t = top_fraction * H;
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
            << "\n set C2 = 0, 0\n set Layer thicknesses = " << H - t << ", "
            << t << "\nend\n"
            << "subsection Contact\n set Mode = nip angle\n set Values = 3\n"
            << " set Indenter radius = 76.2\nend\n";
        const auto  p = testing::parameters_from_string(prm.str());
        RollProblem problem(p, MPI_COMM_WORLD);
        problem.setup();
        InverseContact      contact(problem, p);
        const ContactResult r = contact.solve(theta0);
        const double        K =
          (H * H * H - t * t * t) / (3 * G1) + t * t * t / (3 * G2);
        const double P_thin    = 2 * std::pow(a, 5) / (45 * R_effective * K);
        const auto   one_layer = [&](const double G) {
          return 2 * G * std::pow(a, 5) / (15 * R_effective * H * H * H);
        };
        const std::string at = "G1 = " + testing::num(G1) +
                               ", G2 = " + testing::num(G2) + " MPa, top " +
                               testing::num(t) +
                               " mm, a/H = " + testing::num(a / H) + ": ";
        checker.check(r.converged && r.conformity < 1e-6,
                      at + "converged, conformity " +
                        testing::num(r.conformity));
        series.load.push_back(r.nip_load);
        series.excess.push_back(r.nip_load / P_thin - 1);
        std::cout << "  " << at << "P = " << r.nip_load
                  << " N/mm, P_thin(layered) = " << P_thin
                  << " N/mm, ratio = " << r.nip_load / P_thin
                  << "; one-layer formula with G1: " << one_layer(G1)
                  << ", with G2: " << one_layer(G2) << " N/mm" << std::endl;
      }
    return series;
  }

  /// P_FE / P_thin approaches 1 from above at first order in H/a.
  void
  check_approach(testing::Checker &checker, const std::vector<double> &excess)
  {
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

  /// A thin stiff top coat against one layer of the base material.
  void
  check_top_coat(testing::Checker &checker)
  {
    const double G = 0.5, G_coat = 5, fraction = 0.25;
    const Series coat   = thin_layered_series(checker, G, G_coat, fraction);
    const Series single = thin_layered_series(checker, G, G, fraction);
    check_approach(checker, coat.excess);
    const double f = fraction;
    const double K_ratio =
      1. / (1 - f * f * f + f * f * f * G / G_coat); // K_single / K_coat
    std::vector<double> ratio;
    for (unsigned int i = 0; i < coat.load.size(); ++i)
      ratio.push_back(coat.load[i] / single.load[i]);
    checker.check(ratio[0] > ratio[1] && ratio[1] > ratio[2] &&
                    ratio[2] > K_ratio,
                  "top coat over one layer: P ratio " + testing::num(ratio[0]) +
                    ", " + testing::num(ratio[1]) + ", " +
                    testing::num(ratio[2]) +
                    " at a/H = 8, 16, 32 falls towards " +
                    testing::num(K_ratio) + " of thin-layer theory");
    // As in check_approach: the first-order extrapolation leaves a second
    // order remainder, about the square of the last ratio - 1 (0.2): 0.04.
    const double limit = 2 * ratio[2] - ratio[1];
    checker.check(std::abs(limit - K_ratio) < 0.04,
                  "top coat over one layer: P ratio extrapolated to H/a = 0 " +
                    testing::num(limit) + " within 0.04 of " +
                    testing::num(K_ratio));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  for (const auto &moduli :
       std::vector<std::pair<double, double>>{{0.5, 2.}, {2., 0.5}})
    check_approach(
      checker,
      thin_layered_series(checker, moduli.first, moduli.second, 0.5).excess);
  check_top_coat(checker);
  return checker.result();
}
