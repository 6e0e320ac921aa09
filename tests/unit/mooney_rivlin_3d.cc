// The Mooney-Rivlin law (material/mooney_rivlin_law.h) at d = 3 against
// d = 2, and d = 2 against the plane-strain law written out independently
// here: at a plane-strain F (F33 = 1, no out-of-plane shear) the 3D P, its
// derivative along in-plane dF, cof F and the Cauchy stress (sigma_zz
// included) must equal the 2D law's to round-off, and the 2D law must equal
// the written-out one (its tangent against central differences). For a
// general 3D F the tangent is checked against central differences of P,
// and P against objectivity (P(QF) = Q P(F)).

#include <deal.II/physics/transformations.h>

#include <rollnip/material/mooney_rivlin_law.h>

#include "random_tensor.h"
#include "test_tools.h"

#include <random>

using namespace rollnip;
using testing::random_tensor;

namespace
{
  Tensor<2, 3>
  embed(const Tensor<2, 2> &F2)
  {
    Tensor<2, 3> F;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        F[i][j] = F2[i][j];
    F[2][2] = 1.;
    return F;
  }

  /// The plane-strain law of doc/intro.md, eqs. 2.3 and 2.4, written out
  /// for a 2x2 F: P = 2 C1 F + 2 C2 (I1 F - F F^T F) + (q - q_ref) cof F
  /// with I1 = |F|^2 + 1, and sigma_zz = (2 C1 + 2 C2 (I1 - 1)) / J + q -
  /// q_ref.
  struct PlaneStrainReference
  {
    double C1, C2;

    Tensor<2, 2>
    piola(const Tensor<2, 2> &F, const double q) const
    {
      Tensor<2, 2> cof;
      cof[0][0]       = F[1][1];
      cof[1][1]       = F[0][0];
      cof[0][1]       = -F[1][0];
      cof[1][0]       = -F[0][1];
      const double I1 = F.norm_square() + 1.;
      return 2 * C1 * F + 2 * C2 * (I1 * F - F * transpose(F) * F) +
             (q - 2 * C1 - 4 * C2) * cof;
    }

    double
    sigma_zz(const Tensor<2, 2> &F, const double q) const
    {
      const double J = F[0][0] * F[1][1] - F[0][1] * F[1][0];
      return (2 * C1 + 2 * C2 * F.norm_square()) / J + q - 2 * C1 - 4 * C2;
    }
  };

  /// max |A_ij - B_ij| over the in-plane block, and max |A_i3|, |A_3i|.
  std::pair<double, double>
  plane_difference(const Tensor<2, 3> &A, const Tensor<2, 2> &B)
  {
    double in = 0, out = 0;
    for (unsigned int i = 0; i < 2; ++i)
      {
        for (unsigned int j = 0; j < 2; ++j)
          in = std::max(in, std::abs(A[i][j] - B[i][j]));
        out = std::max({out, std::abs(A[i][2]), std::abs(A[2][i])});
      }
    return {in, out};
  }
  /// General 3D states: the tangent against central differences of P, and
  /// objectivity P(Q F) = Q P(F) for a rotation Q.
  void
  check_general_states(testing::Checker         &check,
                       const MooneyRivlinLaw<3> &law3,
                       std::mt19937             &gen)
  {
    const Tensor<2, 3> I3   = unit_symmetric_tensor<3>();
    double             d_fd = 0, d_obj = 0;
    for (unsigned int sample = 0; sample < 20; ++sample)
      {
        const Tensor<2, 3> F  = I3 + random_tensor<3>(gen, 0.3);
        const Tensor<2, 3> dF = random_tensor<3>(gen, 1.);
        const double       q  = std::uniform_real_distribution<>(-2, 2)(gen);
        const double       h  = 1e-5;
        const Tensor<2, 3> fd =
          (law3.piola(F + h * dF, q) - law3.piola(F - h * dF, q)) / (2 * h);
        d_fd = std::max(d_fd,
                        (fd - law3.piola_derivative(F, q, dF)).norm() /
                          law3.piola_derivative(F, q, dF).norm());
        Tensor<1, 3>       axis({0.3, -0.5, 0.8});
        const Tensor<2, 3> Q =
          Physics::Transformations::Rotations::rotation_matrix_3d(
            Point<3>(axis / axis.norm()), 0.7 + sample);
        d_obj =
          std::max(d_obj, (law3.piola(Q * F, q) - Q * law3.piola(F, q)).norm());
      }
    check.check(d_fd < 1e-8,
                "3D tangent against central differences: max "
                "relative diff " +
                  testing::num(d_fd));
    check.check(d_obj < 1e-12,
                "objectivity P(QF) = Q P(F): max diff " + testing::num(d_obj));
  }
} // namespace

int
main()
{
  testing::Checker           check;
  std::mt19937               gen(22);
  const double               C1 = 0.3, C2 = 0.2;
  const PlaneStrainReference reference{C1, C2};
  const MooneyRivlinLaw<2>   law2(C1, C2);
  const MooneyRivlinLaw<3>   law3(C1, C2);
  const Tensor<2, 2>         I2 = unit_symmetric_tensor<2>();

  double d_P = 0, d_out = 0, d_dP = 0, d_cof = 0, d_sigma = 0, d_zz = 0,
         d_tmpl = 0, d_fd2 = 0;
  for (unsigned int sample = 0; sample < 50; ++sample)
    {
      const Tensor<2, 2> F2  = I2 + random_tensor<2>(gen, 0.4);
      const Tensor<2, 2> dF2 = random_tensor<2>(gen, 1.);
      const double       q   = std::uniform_real_distribution<>(-2, 2)(gen);
      const Tensor<2, 3> F3 = embed(F2), dF3 = embed(dF2) - [] {
        Tensor<2, 3> e;
        e[2][2] = 1.;
        return e;
      }();
      auto [p_in, p_out] =
        plane_difference(law3.piola(F3, q), law2.piola(F2, q));
      auto [t_in, t_out] = plane_difference(law3.piola_derivative(F3, q, dF3),
                                            law2.piola_derivative(F2, q, dF2));
      auto [c_in, c_out] = plane_difference(law3.pressure_direction(F3),
                                            law2.pressure_direction(F2));
      d_P                = std::max(d_P, p_in);
      d_dP               = std::max(d_dP, t_in);
      d_cof              = std::max(d_cof, c_in);
      d_out              = std::max({d_out, p_out, t_out, c_out});

      const SymmetricTensor<2, 2> sigma2 = law2.cauchy(F2, q);
      const double                zz2    = law2.out_of_plane_stress(F2, q);
      const SymmetricTensor<2, 3> sigma3 = law3.cauchy(F3, q);
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = 0; j < 2; ++j)
          d_sigma = std::max(d_sigma, std::abs(sigma3[i][j] - sigma2[i][j]));
      d_zz = std::max(d_zz, std::abs(sigma3[2][2] - zz2));

      const double       h = 1e-6;
      const Tensor<2, 2> fd =
        (reference.piola(F2 + h * dF2, q) - reference.piola(F2 - h * dF2, q)) /
        (2 * h);
      d_tmpl = std::max(
        {d_tmpl,
         (law2.piola(F2, q) - reference.piola(F2, q)).norm(),
         std::abs(law2.out_of_plane_stress(F2, q) - reference.sigma_zz(F2, q)),
         std::abs(law2.constraint(F2) - determinant(F2) + 1.)});
      d_fd2 =
        std::max(d_fd2,
                 (law2.piola_derivative(F2, q, dF2) - fd).norm() / fd.norm());
    }
  const double tol = 1e-13;
  check.check(d_P < tol,
              "in-plane P, 3D against 2D: max diff " + testing::num(d_P) +
                " MPa");
  check.check(d_out < tol,
              "out-of-plane P_i3, P_3i, dP, cof zero: max " +
                testing::num(d_out));
  check.check(d_dP < tol,
              "in-plane dP[dF], 3D against 2D: max diff " + testing::num(d_dP));
  check.check(d_cof < tol,
              "cof F, 3D against 2D: max diff " + testing::num(d_cof));
  check.check(d_sigma < tol,
              "in-plane Cauchy stress: max diff " + testing::num(d_sigma) +
                " MPa");
  check.check(d_zz < tol,
              "sigma_zz (3D component against eq. 2.4): max "
              "diff " +
                testing::num(d_zz) + " MPa");
  check.check(d_tmpl < tol,
              "d = 2 against the written-out plane-strain P, sigma_zz, J - 1: "
              "max diff " +
                testing::num(d_tmpl));
  check.check(d_fd2 < 1e-8,
              "2D tangent against central differences of the written-out P: "
              "max relative diff " +
                testing::num(d_fd2));

  check_general_states(check, law3, gen);
  return check.result();
}
