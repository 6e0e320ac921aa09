// The compressible cover laws (Material/Poisson ratio, Bulk modulus), in 2D
// (plane strain) and 3D, against closed forms that do not use the laws' code:
// - the Mooney-Rivlin law with q eliminated, q = kappa (J - 1), is
//   hyperelastic with the stored energy
//     W = C1 (I1 - 3) + C2 (I2 - 3) - q_ref (J - 1) + kappa/2 (J - 1)^2,
//   kappa = K - 2 G/3 + 2 C1: its P equals dW/dF by central differences at
//   finite strain;
// - at small strain both theories are Hooke's law with the given nu:
//   uniaxial stress in 3D gives lateral strain -nu eps and stress E eps,
//   E = 2 G (1 + nu); plane strain gives -nu/(1 - nu) eps and
//   E/(1 - nu^2) eps;
// - a homogeneous finite in-plane dilation F = lambda I (plane strain) gives
//   sigma = (2 C2 + kappa)(lambda^2 - 1) I in plane;
// - Bulk modulus = K gives the same law as the Poisson ratio it implies,
//   and the default (nu = 0.5) is the incompressible law, bit for bit.

#include <rollnip/material/compressibility.h>
#include <rollnip/material/law_factory.h>
#include <rollnip/material/mooney_rivlin_law.h>

#include "random_tensor.h"
#include "test_tools.h"

#include <random>

using namespace rollnip;
using testing::random_tensor;

namespace
{
  constexpr double C1 = 0.3, C2 = 0.2; // [MPa], G = 1 MPa

  Parameters::Material
  cover(const double nu, const Parameters::Theory theory)
  {
    Parameters::Material m;
    m.layer_C1            = {C1};
    m.layer_C2            = {C2};
    m.layer_poisson_ratio = {nu};
    m.theory              = theory;
    return m;
  }

  /// The multiplier that satisfies the constraint pointwise.
  template <int d>
  double
  eliminated_q(const MaterialLaw<d> &law, const Tensor<2, d> &F)
  {
    return law.constraint(F) / law.pressure_compliance();
  }

  /// The stored energy of the compressible Mooney-Rivlin law, written with
  /// 3x3 invariants (F33 = 1 for d = 2).
  template <int d>
  double
  energy(const Tensor<2, d> &F, const double kappa)
  {
    Tensor<2, 3> F3;
    F3[2][2] = 1;
    for (unsigned int i = 0; i < d; ++i)
      for (unsigned int j = 0; j < d; ++j)
        F3[i][j] = F[i][j];
    const Tensor<2, 3> C  = transpose(F3) * F3;
    const double       I1 = trace(C);
    const double       I2 = 0.5 * (I1 * I1 - trace(C * C));
    const double       J  = determinant(F3);
    return C1 * (I1 - 3) + C2 * (I2 - 3) - (2 * C1 + 4 * C2) * (J - 1) +
           0.5 * kappa * (J - 1) * (J - 1);
  }

  template <int d>
  void
  check_energy(testing::Checker &check, std::mt19937 &gen, const double nu)
  {
    const auto law =
      make_layer_law<d>(cover(nu, Parameters::Theory::nonlinear), 0);
    const double       G     = 2 * (C1 + C2);
    const double       K     = 2 * G * (1 + nu) / (3 * (1 - 2 * nu));
    const double       kappa = K - 2 * G / 3 + 2 * C1;
    const Tensor<2, d> F =
      unit_symmetric_tensor<d>() + random_tensor<d>(gen, 0.3);
    const Tensor<2, d> P     = law->piola(F, eliminated_q(*law, F));
    double             error = 0;
    const double       h     = 1e-5;
    for (unsigned int i = 0; i < d; ++i)
      for (unsigned int j = 0; j < d; ++j)
        {
          Tensor<2, d> dF;
          dF[i][j] = h;
          const double dW =
            (energy<d>(F + dF, kappa) - energy<d>(F - dF, kappa)) / (2 * h);
          error = std::max(error, std::abs(dW - P[i][j]));
        }
    check.check(error < 1e-7 * P.norm(),
                std::to_string(d) + "D, nu = " + testing::num(nu) +
                  ": P(F, q = kappa (J - 1)) = dW/dF at J = " +
                  testing::num(determinant(F)) + ", max difference " +
                  testing::num(error) + " MPa");
  }

  /// The lateral stretch t of uniaxial stress (3D) or plane strain (2D)
  /// F = diag(1 + eps, t, t) at which the lateral stress P22 vanishes.
  template <int d>
  Tensor<2, d>
  uniaxial(const MaterialLaw<d> &law, const double eps)
  {
    auto F_of = [&](const double t) {
      Tensor<2, d> F;
      F[0][0] = 1 + eps;
      for (unsigned int i = 1; i < d; ++i)
        F[i][i] = 1 + t;
      return F;
    };
    auto P22 = [&](const double t) {
      const Tensor<2, d> F = F_of(t);
      return law.piola(F, eliminated_q(law, F))[1][1];
    };
    // P22 increases with t: bisection on [-eps, eps].
    double lo = -eps, hi = eps;
    for (int i = 0; i < 200; ++i)
      {
        const double mid         = 0.5 * (lo + hi);
        (P22(mid) < 0 ? lo : hi) = mid;
      }
    return F_of(0.5 * (lo + hi));
  }

  template <int d>
  void
  check_hooke(testing::Checker        &check,
              const double             nu,
              const Parameters::Theory theory)
  {
    const auto         law   = make_layer_law<d>(cover(nu, theory), 0);
    const double       G     = 2 * (C1 + C2);
    const double       eps   = 1e-6;
    const Tensor<2, d> F     = uniaxial(*law, eps);
    const double       ratio = -(F[1][1] - 1) / eps;
    const double stiffness   = law->piola(F, eliminated_q(*law, F))[0][0] / eps;
    const double E           = 2 * G * (1 + nu);
    const double ratio_exact = d == 3 ? nu : nu / (1 - nu);
    const double stiff_exact = d == 3 ? E : E / (1 - nu * nu);
    const std::string name =
      std::string(theory == Parameters::Theory::linear ? "linear"
                                                       : "nonlinear") +
      " " + std::to_string(d) + "D, nu = " + testing::num(nu) + ": ";
    const double ratio_error =
      ratio_exact == 0 ? std::abs(ratio) : std::abs(ratio / ratio_exact - 1);
    check.check(ratio_error < 1e-5 &&
                  std::abs(stiffness / stiff_exact - 1) < 1e-5,
                name + "lateral/axial strain " + testing::num(ratio) +
                  " (Hooke " + testing::num(ratio_exact) + "), stress/strain " +
                  testing::num(stiffness) + " MPa (Hooke " +
                  testing::num(stiff_exact) + " MPa)");
  }

  /// Plane-strain dilation F = lambda I (2D): sigma = (2 C2 + kappa)
  /// (lambda^2 - 1) I in plane, from P = 2 C1 F + 2 C2 (I1 F - F C) +
  /// (q - q_ref) cof F with I1 = 2 lambda^2 + 1 and cof F = lambda I.
  void
  check_dilation_2d(testing::Checker &check, const double nu)
  {
    const auto law =
      make_layer_law<2>(cover(nu, Parameters::Theory::nonlinear), 0);
    const double       G      = 2 * (C1 + C2);
    const double       K      = 2 * G * (1 + nu) / (3 * (1 - 2 * nu));
    const double       kappa  = K - 2 * G / 3 + 2 * C1;
    const double       lambda = 0.8;
    const Tensor<2, 2> F = lambda * Tensor<2, 2>(unit_symmetric_tensor<2>());
    const auto         sigma = law->cauchy(F, eliminated_q(*law, F));
    const double       exact = (2 * C2 + kappa) * (lambda * lambda - 1);
    check.check(std::abs(sigma[0][0] - exact) < 1e-12 &&
                  std::abs(sigma[1][1] - exact) < 1e-12 &&
                  std::abs(sigma[0][1]) < 1e-12,
                "2D, nu = " + testing::num(nu) + ": dilation 0.8, sigma " +
                  testing::num(sigma[0][0]) + " MPa (closed form " +
                  testing::num(exact) + " MPa)");
  }

  /// Bulk modulus = K: the same law as the Poisson ratio it implies; the
  /// default entries: the incompressible law, bit for bit.
  void
  check_entries(testing::Checker &check, std::mt19937 &gen)
  {
    const double         nu   = 0.45;
    Parameters::Material by_K = cover(0.5, Parameters::Theory::nonlinear);
    by_K.layer_bulk_modulus   = {
        Compressibility::bulk_modulus(cover(nu, Parameters::Theory::nonlinear),
                                    0)};
    const auto a = make_layer_law<3>(by_K, 0);
    const auto b =
      make_layer_law<3>(cover(nu, Parameters::Theory::nonlinear), 0);
    const Tensor<2, 3> F =
      unit_symmetric_tensor<3>() + random_tensor<3>(gen, 0.3);
    check.check(std::abs(a->pressure_compliance() / b->pressure_compliance() -
                         1) < 1e-14 &&
                  std::abs(Compressibility::poisson_ratio(by_K, 0) - nu) <
                    1e-14,
                "Bulk modulus " + testing::num(by_K.layer_bulk_modulus[0]) +
                  " MPa is Poisson ratio " +
                  testing::num(Compressibility::poisson_ratio(by_K, 0)));
    const auto incompressible =
      make_layer_law<3>(cover(0.5, Parameters::Theory::nonlinear), 0);
    const MooneyRivlinLaw<3> reference(C1, C2);
    check.check(incompressible->pressure_compliance() == 0 &&
                  incompressible->piola(F, 0.1) == reference.piola(F, 0.1) &&
                  incompressible->constraint(F) == reference.constraint(F),
                "Poisson ratio 0.5: the incompressible law, bit for bit");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 check;
  std::mt19937                     gen(7);
  for (const double nu : {0.3, 0.45, 0.49})
    {
      check_energy<2>(check, gen, nu);
      check_energy<3>(check, gen, nu);
      check_dilation_2d(check, nu);
    }
  for (const double nu : {0.1, 0.3, 0.45, 0.499})
    for (const auto theory :
         {Parameters::Theory::nonlinear, Parameters::Theory::linear})
      {
        check_hooke<2>(check, nu, theory);
        check_hooke<3>(check, nu, theory);
      }
  check_hooke<3>(check, 0., Parameters::Theory::nonlinear);
  check_entries(check, gen);
  return check.result();
}
