// The Prony-series viscoelastic law (material/viscoelastic_law.h).
// - Elastic limit: with g = 0 every evaluation equals the Mooney-Rivlin
//   law's exactly, in 2D and 3D, after committed steps.
// - Relaxation: uniaxial stretch (3D, traction-free sides through q) at
//   small strain, ramped over t_r and held, against the standard linear
//   solid's closed form: E(t) = E (1 + g e^(-t/tau)) with E = 3 G, i.e.
//   sigma = E eps + g E r tau (1 - e^(-t/tau)) on the ramp (rate r) and the
//   Maxwell stress decaying as e^(-(t - t_r)/tau) after it; two branches
//   superpose.
// - The tangent against central differences of P at a viscous state, in
//   2D and 3D, and rollback() returning to the committed state.

#include <rollnip/material/mooney_rivlin_law.h>
#include <rollnip/material/viscoelastic_law.h>

#include "random_tensor.h"
#include "test_tools.h"

#include <cmath>
#include <random>

using namespace rollnip;
using testing::random_tensor;

namespace
{
  /// Largest difference of every evaluation of @p visco and @p elastic
  /// over a few random states, each followed by a committed step.
  template <int d>
  double
  elastic_limit_difference(std::mt19937 &gen)
  {
    const double             C1 = 0.3, C2 = 0.1;
    ViscoelasticLaw<d>       visco(C1, C2, {{0., 0.5}, {0., 2.}});
    const MooneyRivlinLaw<d> elastic(C1, C2);
    double                   diff = 0;
    for (unsigned int step = 0; step < 5; ++step)
      {
        visco.set_time_increment(0.1);
        const Tensor<2, d> F =
          unit_symmetric_tensor<d>() + random_tensor<d>(gen, 0.3);
        const Tensor<2, d> dF = random_tensor<d>(gen, 1.);
        const double       q  = 0.4;
        diff                  = std::max({diff,
                                          (visco.piola(F, q) - elastic.piola(F, q)).norm(),
                                          (visco.piola_derivative(F, q, dF) -
                          elastic.piola_derivative(F, q, dF))
                                            .norm(),
                                          (visco.cauchy(F, q) - elastic.cauchy(F, q)).norm(),
                                          std::abs(visco.out_of_plane_stress(F, q) -
                                  elastic.out_of_plane_stress(F, q))});
        visco.commit();
      }
    return diff;
  }

  /// sigma_11 of uniaxial stretch 1 + eps with sigma_22 = sigma_33 = 0.
  double
  uniaxial_stress(const ViscoelasticLaw<3> &law, const double eps)
  {
    const double lambda = 1. + eps;
    Tensor<2, 3> F;
    F[0][0] = lambda;
    F[1][1] = F[2][2] = 1. / std::sqrt(lambda);
    // sigma is affine in q with slope I: q makes the sides traction free.
    const SymmetricTensor<2, 3> s0 = law.cauchy(F, 0.);
    return law.cauchy(F, -s0[1][1])[0][0];
  }

  /// The standard linear solid (one branch per term) at time t for a
  /// strain ramped at rate r up to t_r and held.
  double
  linear_solid(const double                  E,
               const std::vector<PronyTerm> &terms,
               const double                  r,
               const double                  t_r,
               const double                  t)
  {
    double sigma = E * r * std::min(t, t_r);
    for (const auto &b : terms)
      sigma += b.g * E * r * b.tau * (1 - std::exp(-std::min(t, t_r) / b.tau)) *
               std::exp(-std::max(t - t_r, 0.) / b.tau);
    return sigma;
  }
} // namespace

int
main()
{
  testing::Checker check;
  std::mt19937     gen(7);

  const double d2 = elastic_limit_difference<2>(gen);
  const double d3 = elastic_limit_difference<3>(gen);
  check.check(d2 == 0 && d3 == 0,
              "g = 0: P, dP, sigma, sigma_zz equal the Mooney-Rivlin law's "
              "exactly (max diff 2D " +
                testing::num(d2) + ", 3D " + testing::num(d3) + ")");

  // Relaxation at small strain: two branches, ramp over t_r, then hold.
  const double                 C1 = 0.4, C2 = 0.1, E = 3 * 2 * (C1 + C2);
  const std::vector<PronyTerm> terms = {{0.8, 1.}, {0.3, 0.1}};
  ViscoelasticLaw<3>           law(C1, C2, terms);
  const double eps0 = 1e-4, t_r = 0.5, r = eps0 / t_r, dt = 0.01;
  double       worst = 0, t = 0, peak = 0;
  for (unsigned int n = 1; t < 6. - 1e-12; ++n)
    {
      t = n * dt;
      law.set_time_increment(dt);
      const double sigma = uniaxial_stress(law, r * std::min(t, t_r));
      law.commit();
      const double exact = linear_solid(E, terms, r, t_r, t);
      worst              = std::max(worst, std::abs(sigma - exact));
      peak               = std::max(peak, sigma);
    }
  const double relaxed = uniaxial_stress(law, eps0);
  check.check(worst < 2e-4 * E * eps0,
              "uniaxial relaxation against the linear solid, eps = 1e-4, "
              "t in [0, 6]: max |sigma - exact| / (E eps) = " +
                testing::num(worst / (E * eps0)) + " < 2e-4");
  check.check(peak > 1.3 * E * eps0 &&
                std::abs(relaxed - E * eps0) < 3e-3 * E * eps0,
              "peak sigma / (E eps) = " + testing::num(peak / (E * eps0)) +
                " > 1.3; relaxed to " + testing::num(relaxed / (E * eps0)) +
                " (long-term modulus, within the strain's O(eps) and "
                "e^-5.5 of the slow branch)");

  // The tangent at a viscous state, and rollback.
  ViscoelasticLaw<2> law2(C1, C2, terms);
  ViscoelasticLaw<3> law3(C1, C2, terms);
  double             fd2 = 0, fd3 = 0;
  for (unsigned int step = 0; step < 4; ++step)
    {
      law2.set_time_increment(0.05);
      law3.set_time_increment(0.05);
      const Tensor<2, 2> F2 =
        unit_symmetric_tensor<2>() + random_tensor<2>(gen, 0.3);
      const Tensor<2, 3> F3 =
        unit_symmetric_tensor<3>() + random_tensor<3>(gen, 0.3);
      const Tensor<2, 2> dF2 = random_tensor<2>(gen, 1.);
      const Tensor<2, 3> dF3 = random_tensor<3>(gen, 1.);
      const double       h = 1e-6, q = 0.2;
      const Tensor<2, 2> c2 =
        (law2.piola(F2 + h * dF2, q) - law2.piola(F2 - h * dF2, q)) / (2 * h);
      const Tensor<2, 3> c3 =
        (law3.piola(F3 + h * dF3, q) - law3.piola(F3 - h * dF3, q)) / (2 * h);
      fd2 =
        std::max(fd2,
                 (law2.piola_derivative(F2, q, dF2) - c2).norm() / c2.norm());
      fd3 =
        std::max(fd3,
                 (law3.piola_derivative(F3, q, dF3) - c3).norm() / c3.norm());
      law2.piola(F2, q);
      law3.piola(F3, q);
      law2.commit();
      law3.commit();
    }
  check.check(fd2 < 1e-7 && fd3 < 1e-7,
              "tangent against central differences at a viscous state: "
              "max relative diff 2D " +
                testing::num(fd2) + ", 3D " + testing::num(fd3));

  // A trial that is rolled back leaves no trace: committing after it
  // holds the last committed F, as a law that never saw the trial does.
  const Tensor<2, 2> F =
    unit_symmetric_tensor<2>() + random_tensor<2>(gen, 0.2);
  ViscoelasticLaw<2> a(C1, C2, terms), b(C1, C2, terms);
  for (auto *law : {&a, &b})
    {
      law->set_time_increment(0.1);
      law->piola(F, 0.);
      law->commit();
    }
  a.piola(2. * F, 0.); // a trial that fails
  a.rollback();
  a.commit();
  b.commit();
  const double after = (a.piola(F, 0.) - b.piola(F, 0.)).norm();
  check.check(after == 0,
              "rollback() drops a trial: the step after it equals one "
              "without the trial (diff " +
                testing::num(after) + ")");
  return check.result();
}
