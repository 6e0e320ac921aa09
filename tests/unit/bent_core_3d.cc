// Stage 3 of the 3D body: a rigid core with a prescribed bending line v(z)
// (Three d/Core deflection, three_d/core_deflection.h). Truths:
// - a constant v is a uniform shift of the approach: u0 with v = c is the
//   straight core at u0 - c, to the Newton tolerance (the same body moved
//   rigidly by c);
// - a core bent over a length much longer than the nip (a half cosine
//   over 2000 mm, the approach ranging over 1..2 mm) carries at every node
//   plane the plane-strain line load of its local approach, P(u0 - v(z)),
//   computed by the slice of stage 1 (u_z = 0 on both faces, one cell
//   thick) on the same cross-section mesh;
// - a short ripple is smoothed: its transfer T (the ripple of q over that
//   of the local law) lies in (0, 1), falls with the wavenumber and does
//   not depend on the axial cells.

#include <rollnip/three_d/slice_body.h>

#include "test_tools.h"
#include "three_d_test_tools.h"

#include <algorithm>
#include <cmath>

using namespace rollnip;

namespace
{
  const std::string scene = testing::run30_indentation_scene("1");

  Parameters::ThreeD
  slice(const double       thickness,
        const unsigned int layers,
        const std::string &deflection)
  {
    auto t            = testing::slice_parameters(thickness, layers);
    t.core_deflection = deflection;
    return t;
  }

  /// The line load at the node planes (consistent recovery).
  std::vector<std::pair<double, double>>
  line_load(const Parameters::AllParameters &parameters,
            const Parameters::ThreeD        &t,
            const double                     u0)
  {
    three_d::SliceBody body(parameters, t, 0, MPI_COMM_WORLD);
    body.solve(u0);
    return three_d::consistent_line_load(body.line_load_profile());
  }

  /// The ripple's transfer at wavelength @p lambda on @p layers cells
  /// per half wave, for a local ripple of @p local N/mm.
  double
  transfer(const Parameters::AllParameters &parameters,
           const double                     lambda,
           const unsigned int               layers,
           const double                     amplitude,
           const double                     local)
  {
    const auto q = line_load(parameters,
                             slice(lambda / 2,
                                   layers,
                                   std::to_string(amplitude) + "*cos(2*pi*z/" +
                                     std::to_string(lambda) + ")"),
                             1.);
    // The cos(k z) coefficient of the piecewise linear q (trapezoidal
    // sums over a half period are exact for cos and its harmonics up to
    // the number of cells).
    const double h  = q[1].first - q[0].first;
    double       c1 = 0;
    for (unsigned int j = 0; j < q.size(); ++j)
      c1 += (j == 0 || j + 1 == q.size() ? 0.5 : 1.) * q[j].second *
            std::cos(2 * numbers::PI * q[j].first / lambda);
    c1 *= 2 * h / (lambda / 2);
    const double T = -c1 / local;
    const double l = 0.63 * 7.323;
    const double k = 2 * numbers::PI / lambda;
    std::cout << "ripple lambda = " << lambda << " mm, " << layers
              << " layers: ripple of q " << testing::num(-c1)
              << " N/mm, T = " << testing::num(T)
              << " (face model, l = 0.63 a: "
              << testing::num(1 / (1 + k * k * l * l)) << ")" << std::endl;
    return T;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 check;
  const auto parameters = testing::parameters_from_string(scene);

  // v = const: the straight core at the shifted approach.
  {
    three_d::SliceBody bent(parameters, slice(2, 2, "0.3"), 0, MPI_COMM_WORLD);
    three_d::SliceBody straight(parameters,
                                slice(2, 2, "0"),
                                0,
                                MPI_COMM_WORLD);
    const three_d::SliceNip a = bent.solve(1.);
    const three_d::SliceNip b = straight.solve(0.7);
    check.check(std::abs(a.P / b.P - 1) < 1e-9 &&
                  a.active_nodes == b.active_nodes &&
                  std::abs(a.half_chord - b.half_chord) < 1e-9,
                "v = 0.3 mm at u0 = 1 mm: P = " + testing::num(a.P) +
                  " N/mm, " + std::to_string(a.active_nodes) +
                  " active nodes; straight core at 0.7 mm: P = " +
                  testing::num(b.P) + " N/mm, " +
                  std::to_string(b.active_nodes) + " nodes, relative diff " +
                  testing::num(a.P / b.P - 1));
  }

  // A long bend: the local law at every node plane.
  {
    const double u0 = 1.5, amplitude = 0.5, lambda = 4000;
    const auto   q =
      line_load(parameters, slice(lambda / 2, 8, "0.5*cos(2*pi*z/4000)"), u0);
    std::vector<std::pair<double, unsigned int>> local; // (delta, plane)
    for (unsigned int j = 0; j < q.size(); ++j)
      local.emplace_back(u0 - amplitude *
                                std::cos(2 * numbers::PI * q[j].first / lambda),
                         j);
    std::sort(local.begin(), local.end());
    three_d::SliceBody plane_strain(parameters,
                                    slice(1, 1, "0"),
                                    0,
                                    MPI_COMM_WORLD);
    double             worst = 0;
    for (const auto &[delta, j] : local)
      {
        const double P = plane_strain.solve(delta).P;
        const double e = q[j].second / P - 1;
        worst          = std::max(worst, std::abs(e));
        std::cout << "z = " << q[j].first
                  << " mm, u0 - v = " << testing::num(delta)
                  << " mm: q = " << testing::num(q[j].second)
                  << " N/mm, plane strain " << testing::num(P) << " N/mm ("
                  << testing::num(100 * e) << " %)" << std::endl;
      }
    check.check(worst < 6e-3,
                "bent core over 2000 mm: q(z) within 0.6 % of the plane-strain "
                "P(u0 - v(z)) at every plane, worst " +
                  testing::num(100 * worst) + " %");
  }

  // Short ripples: smoothed, more the shorter, independent of the cells.
  {
    const double       amplitude = 0.2;
    three_d::SliceBody plane_strain(parameters,
                                    slice(1, 1, "0"),
                                    0,
                                    MPI_COMM_WORLD);
    const double       below = plane_strain.solve(1 - amplitude).P;
    const double       above = plane_strain.solve(1 + amplitude).P;
    const double       local = (above - below) / 2;
    const double       T60   = transfer(parameters, 60, 8, amplitude, local);
    const double       T30   = transfer(parameters, 30, 8, amplitude, local);
    const double T30_fine    = transfer(parameters, 30, 16, amplitude, local);
    check.check(0 < T30 && T30 < T60 && T60 < 1,
                "transfer 0 < T(30 mm) = " + testing::num(T30) +
                  " < T(60 mm) = " + testing::num(T60) + " < 1");
    check.check(std::abs(T30_fine - T30) < 0.02,
                "T(30 mm) on 16 cells per half wave " + testing::num(T30_fine) +
                  " against 8: " + testing::num(T30));
  }
  return check.result();
}
