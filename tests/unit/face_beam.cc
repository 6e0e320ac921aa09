// The face model's beams and their foundation against closed forms
// (doc/face.md, "Validation"):
// 1. a uniformly loaded simply supported beam without foundation:
//    w(L/2) = 5 q L^4 / (384 EI) + q L^2 / (8 kappa G A), exact at the
//    nodes of the exact Timoshenko element on any mesh;
// 2. Hetenyi's beam of finite length on a Winkler foundation loaded by
//    two end forces (derived below), Euler-Bernoulli: centre and end
//    approaches to 1e-4 relative, and their convergence in the 1D mesh;
// 3. the monotone log-log interpolant reproduces a power law exactly and
//    its derivative is the interpolant's slope.
#include <rollnip/face/beam.h>
#include <rollnip/face/face_solver.h>
#include <rollnip/face/foundation_law.h>

#include "test_tools.h"

#include <cmath>

using namespace rollnip;
using namespace rollnip::Face;
using testing::num;

namespace
{
  /**
   * Hetenyi (1946): EI w'''' + k w = 0 on |x| <= L/2, free ends loaded
   * by P each into the foundation, w the approach. With xi = lambda x,
   * lambda = (k / 4 EI)^(1/4), the symmetric solution is w = A cosh xi
   * cos xi + B sinh xi sin xi. f1 = cosh cos, f2 = sinh sin have f1'' =
   * -2 f2, f2'' = 2 f1, f1''' = -2 f2', f2''' = 2 f1'. The free end has
   * no moment, w''(L/2) = 0: B f1 = A f2 at xi_e = lambda L / 2; its
   * shear carries P, and int k w = 2 P gives EI w'''(L/2) = -P:
   * EI lambda^3 (-2 A f2' + 2 B f1') = -P. Returns (w(0), w(L/2)).
   */
  std::pair<double, double>
  hetenyi(const double EI, const double k, const double L, const double P)
  {
    const double lambda = std::pow(k / (4 * EI), 0.25);
    const double e      = lambda * L / 2;
    const double f1     = std::cosh(e) * std::cos(e),
                 f2     = std::sinh(e) * std::sin(e);
    const double d1 = std::sinh(e) * std::cos(e) - std::cosh(e) * std::sin(e);
    const double d2 = std::cosh(e) * std::sin(e) + std::sinh(e) * std::cos(e);
    // B = A f2 / f1; -2 A d2 + 2 A f2 / f1 d1 = -P / (EI lambda^3).
    const double A =
      -P / (EI * std::pow(lambda, 3)) / (-2 * d2 + 2 * f2 / f1 * d1);
    const double B = A * f2 / f1;
    return {A, A * f1 + B * f2};
  }

  void
  check_simply_supported(testing::Checker &checker)
  {
    std::cout << "1. Uniformly loaded simply supported beam" << std::endl;
    Parameters::FaceCore core{94.4, 60, 210000, 0.3, 7850};
    for (const bool shear : {false, true})
      for (const unsigned int n : {4u, 10u})
        {
          const BeamSection     s = tube_section(core, shear);
          const double          L = 800, q = 15;
          const FaceMesh        mesh(L, L, n);
          const Eigen::VectorXd w = simply_supported_deflection(mesh, s, q, 0);
          const double          exact =
            5 * q * std::pow(L, 4) / (384 * s.bending_stiffness) +
            (shear ? q * L * L / (8 * s.shear_stiffness) : 0.);
          const double mid = w[2 * (n / 2)];
          checker.check(std::abs(mid / exact - 1) < 1e-10,
                        std::string(shear ? "Timoshenko" : "Euler-Bernoulli") +
                          ", " + std::to_string(n) + " elements: w(L/2) = " +
                          num(mid) + " mm, closed form " + num(exact) + " mm");
        }
  }

  void
  check_hetenyi(testing::Checker &checker)
  {
    std::cout << "2. Hetenyi's end-loaded beam on a Winkler foundation"
              << std::endl;
    Parameters::FaceCore core{94.4, 60, 210000, 0.3, 7850};
    const BeamSection    s = tube_section(core, false);
    const double         L = 1000, P = 10000;
    // lambda L = 2.5: the beam bends visibly but the centre stays in.
    const double lambda      = 2.5 / L;
    const double k           = 4 * s.bending_stiffness * std::pow(lambda, 4);
    const auto [centre, end] = hetenyi(s.bending_stiffness, k, L, P);
    LinearFoundation law(k);
    FaceModel        model;
    model.face_length      = L;
    model.bearing_distance = L;
    model.roll             = s;
    model.total_force      = 2 * P;
    model.law              = &law;
    std::vector<double> errors;
    for (const unsigned int n : {8u, 16u, 32u, 100u})
      {
        model.elements          = n;
        const FaceSolution face = solve_face(model);
        const double       c = face.approach_at(0), e = face.approach_at(L / 2);
        const double       err =
          std::max(std::abs(c / centre - 1), std::abs(e / end - 1));
        errors.push_back(err);
        std::cout << "  " << n << " elements: delta(0) = " << num(c)
                  << " mm (closed form " << num(centre)
                  << "), delta(L/2) = " << num(e) << " mm (" << num(end)
                  << "), error " << num(err) << std::endl;
      }
    checker.check(errors.back() < 1e-4,
                  "100 elements: centre and end within 1e-4 (" +
                    num(errors.back()) + ")");
    const double order = std::log2(errors[1] / errors[2]);
    checker.check(order > 3.5,
                  "the error falls like h^4 (observed order " + num(order) +
                    " from 16 to 32 elements)");
    checker.check(end > centre && centre > 0,
                  "the ends go in further than the centre, which stays in "
                  "contact (lambda L = 2.5)");
  }

  void
  check_loglog_pchip(testing::Checker &checker)
  {
    std::cout << "3. Monotone log-log interpolation" << std::endl;
    std::vector<double> x, y;
    for (unsigned int i = 0; i < 8; ++i)
      {
        x.push_back(0.05 * std::pow(1.6, i));
        y.push_back(3 * std::pow(x.back(), 1.7));
      }
    const LogLogPchip f(x, y);
    double            worst = 0, worst_slope = 0;
    for (const double t : {0.01, 0.07, 0.3, 1.1, 5.})
      {
        worst =
          std::max(worst, std::abs(f.value(t) / (3 * std::pow(t, 1.7)) - 1));
        worst_slope =
          std::max(worst_slope,
                   std::abs(f.derivative(t) / (5.1 * std::pow(t, 0.7)) - 1));
      }
    checker.check(worst < 1e-12 && worst_slope < 1e-12,
                  "a power law is reproduced in and beyond the samples "
                  "(value " +
                    num(worst) + ", slope " + num(worst_slope) + ")");
    // Data with a flat stretch stays monotone between the samples.
    const LogLogPchip g({1, 2, 3, 4, 5}, {1, 2, 2.0001, 5, 6});
    bool              monotone = true;
    for (double t = 1; t < 5; t += 0.01)
      monotone = monotone && g.value(t + 0.01) >= g.value(t) - 1e-14;
    checker.check(monotone, "the interpolant of monotone data is monotone");
  }
} // namespace

int
main()
{
  testing::Checker checker;
  check_simply_supported(checker);
  check_hetenyi(checker);
  check_loglog_pchip(checker);
  return checker.result();
}
