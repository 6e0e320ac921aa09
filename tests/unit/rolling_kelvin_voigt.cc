// The first-order rolling loss against its closed form (doc/rolling.md,
// section 3). In linear theory a Kelvin-Voigt cover of retardation time
// tau, bonded to a rigid core and pressed by a frictionless rigid cylinder
// of radius Rbar, loses to first order in V tau / b the power
//   W = tau V^2 P / R_eff,   1/R_eff = 1/R0 + 1/Rbar,
// whatever the cover's thickness: F_r = W / V = tau V P / R_eff. The
// post-process integrates 2 G tau |dev(d eps/dt)|^2 along the mesh's
// circles; it must reproduce F_r on a thin cover (h = 1 mm, a/h = 3.2) and
// a thick one (h = 13.5 mm, a/h = 0.24), at theta0 = 3 deg, up to the
// discretisation error: that error falls at first order in the mesh size
// (the strain rate is singular like rho^-1/2 at the contact edges, so the
// loss within a cell of them is O(h)), and the Richardson extrapolation of
// the two finest levels lies within 0.5 % of the closed form. The
// remaining small-nip terms are O(theta0^2, u0/R0), about 0.1 % here.
// Also: zero speed and tau = 0 lose nothing, the loss grows like V^2, a
// Prony series of the same sum g_i tau_i loses the same, and the
// finite-strain isochoric stress tends to linear theory's.

#include <rollnip/contact/inverse_contact.h>
#include <rollnip/rolling/cover_circles.h>
#include <rollnip/rolling/first_order_loss.h>

#include "test_tools.h"

using namespace rollnip;

namespace
{
  constexpr double R0 = 60.7, Rbar = 76.2, tau = 1e-4, V = 1.; // mm, s, m/s
  constexpr double theta0_deg = 3;

  /// The Kelvin-Voigt cover of retardation time @p t.
  Parameters::Rolling
  kelvin_voigt(const double t)
  {
    Parameters::Rolling r;
    r.enabled = true;
    r.model   = Parameters::ViscoelasticModel::kelvin_voigt;
    r.layers  = {{{1.}, {t}}};
    return r;
  }

  /// F_r FE over tau V P / R_eff for the cover of inner radius @p R1 at
  /// mesh level @p level; @p zero_checks also checks V = 0 and tau = 0.
  double
  ratio(const double       R1,
        const unsigned int level,
        testing::Checker  &checker,
        const bool         extra_checks)
  {
    std::ostringstream text;
    text << std::setprecision(15)
         << "subsection Geometry\n set Inner radius = " << R1
         << "\n set Outer radius = " << R0
         << "\nend\nsubsection Mesh\n set Global refinements = " << level
         << "\nend\nsubsection Material\n set Theory = linear\nend\n"
            "subsection Contact\n set Mode = nip angle\n set Values = 3\n"
            " set Indenter radius = 76.2\nend\n";
    const auto  parameters = testing::parameters_from_string(text.str());
    RollProblem problem(parameters, MPI_COMM_WORLD);
    problem.setup();
    InverseContact      contact(problem, parameters);
    const ContactResult r = contact.solve(theta0_deg * numbers::PI / 180);
    checker.check(r.converged, "nip converged (" + r.message + ")");
    const auto circles = cover_circles(problem.body());
    const auto sector  = parameters.geometry.sector_angle;
    const auto loss =
      first_order_loss(circles, kelvin_voigt(tau), R0, sector, V);
    const double R_eff  = 1. / (1. / R0 + 1. / Rbar);
    const double closed = tau * 1e3 * V * r.nip_load / R_eff;
    std::cout << "  h = " << testing::num(R0 - R1) << " mm, level " << level
              << ": P = " << r.nip_load << " N/mm, b = " << r.half_chord
              << " mm, F_r = " << loss.rolling_resistance
              << " N/mm, tau V P / R_eff = " << closed
              << " N/mm, ratio = " << loss.rolling_resistance / closed
              << std::endl;
    if (extra_checks)
      {
        const auto still =
          first_order_loss(circles, kelvin_voigt(tau), R0, sector, 0.);
        const auto elastic =
          first_order_loss(circles, kelvin_voigt(0.), R0, sector, V);
        checker.check(still.power == 0 && still.rolling_resistance == 0 &&
                        elastic.power == 0,
                      "V = 0 and tau = 0 dissipate exactly nothing");
        // A Prony series of the same sum g_i tau_i loses the same to first
        // order.
        Parameters::Rolling prony = kelvin_voigt(tau);
        prony.model               = Parameters::ViscoelasticModel::prony;
        prony.layers              = {{{0.5, 0.125, 2.}, {1e-4, 2e-4, 1.25e-5}}};
        const auto branches = first_order_loss(circles, prony, R0, sector, V);
        checker.check(std::abs(branches.power / loss.power - 1) < 1e-12,
                      "a Prony series with sum g_i tau_i = tau loses as the "
                      "Kelvin-Voigt cover (ratio " +
                        testing::num(branches.power / loss.power) + ")");
        const auto twice =
          first_order_loss(circles, kelvin_voigt(tau), R0, sector, 2 * V);
        checker.check(std::abs(twice.power / loss.power - 4) < 1e-12,
                      "doubling V multiplies the power by " +
                        testing::num(twice.power / loss.power) + " (4)");
      }
    return loss.rolling_resistance / closed;
  }

  /// The finite-strain S_iso at a small displacement gradient over linear
  /// theory's, relative difference.
  double
  small_strain_difference()
  {
    Tensor<2, dim> g;
    g[0][0]              = 1e-7;
    g[0][1]              = 3e-7;
    g[1][0]              = -2e-7;
    g[1][1]              = -0.5e-7;
    const auto nonlinear = isochoric_stress(g, 0.3, 0.1, false);
    const auto linear    = isochoric_stress(g, 0.3, 0.1, true);
    return (nonlinear - linear).norm() / linear.norm();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  const double                     d = small_strain_difference();
  checker.check(d < 1e-5,
                "finite-strain S_iso tends to 2 G dev(eps) at small strain "
                "(relative difference " +
                  testing::num(d) + ")");
  for (const double R1 : {59.7, 47.2})
    {
      std::vector<double> error;
      for (unsigned int level = 0; level <= 3; ++level)
        error.push_back(ratio(R1, level, checker, level == 0) - 1);
      const std::string cover = "h = " + testing::num(R0 - R1) + " mm: ";
      for (unsigned int l = 1; l < error.size(); ++l)
        {
          const double p =
            testing::order(std::abs(error[l - 1]), std::abs(error[l]));
          checker.check(error[l] < 0 && p > 0.7 && p < 1.6,
                        cover +
                          "F_r / closed form - 1 = " + testing::num(error[l]) +
                          " at level " + std::to_string(l) + ", order " +
                          testing::num(p) + " (first order, from below)");
        }
      // Richardson with the first order measured above.
      const double extrapolated = 2 * error[3] - error[2];
      checker.check(std::abs(extrapolated) < 5e-3,
                    cover + "extrapolated F_r / closed form - 1 = " +
                      testing::num(extrapolated) + " (within 0.5 %)");
      checker.check(std::abs(error[3]) < 0.025,
                    cover + "level 3 within 2.5 % of the closed form");
    }
  return checker.result();
}
