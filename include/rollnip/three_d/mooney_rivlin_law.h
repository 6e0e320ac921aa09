#ifndef rollnip_three_d_mooney_rivlin_law_h
#define rollnip_three_d_mooney_rivlin_law_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace rollnip
{
  /**
   * The incompressible Mooney-Rivlin law of doc/intro.md, section 2, for a
   * deformation gradient of any dimension d: d = 3 is the full law of the
   * 3D body, d = 2 the plane-strain law (F33 = 1). One formula serves both:
   *   W = C1 (I1 - 3) + C2 (I2 - 3) + (q - q_ref) (J - 1),
   *   P = 2 C1 F + 2 C2 (I1 F - F C) + (q - q_ref) cof F,   q_ref = 2 C1 + 4 C2
   * with I1 the trace of the 3x3 right Cauchy-Green tensor, i.e.
   * tr C + (3 - d), and cof F = J F^-T. The test mooney_rivlin_3d checks
   * that the 3D law at a plane-strain F reproduces the 2D law.
   */
  template <int d>
  class MooneyRivlinLaw
  {
  public:
    MooneyRivlinLaw(const double C1, const double C2)
        : C1(C1)
        , C2(C2)
        , q_ref(2. * C1 + 4. * C2)
    {}

    /// First Piola-Kirchhoff stress (eq. 2.3).
    dealii::Tensor<2, d>
    piola(const dealii::Tensor<2, d> &F, const double q) const
    {
      const dealii::Tensor<2, d> C = transpose(F) * F;
      return 2. * C1 * F + 2. * C2 * (first_invariant(F) * F - F * C) +
             (q - q_ref) * cofactor(F);
    }

    /// dP[dF] at fixed q.
    dealii::Tensor<2, d>
    piola_derivative(const dealii::Tensor<2, d> &F,
                     const double                q,
                     const dealii::Tensor<2, d> &dF) const
    {
      const dealii::Tensor<2, d> C   = transpose(F) * F;
      const dealii::Tensor<2, d> dC  = transpose(dF) * F + transpose(F) * dF;
      const double               dI1 = 2. * scalar_product(F, dF);
      return 2. * C1 * dF +
             2. * C2 * (dI1 * F + first_invariant(F) * dF - dF * C - F * dC) +
             (q - q_ref) * cofactor_derivative(F, dF);
    }

    /// dP/dq = d(J - 1)/dF = cof F.
    dealii::Tensor<2, d>
    pressure_direction(const dealii::Tensor<2, d> &F) const
    {
      return cofactor(F);
    }

    /// The incompressibility residual J - 1.
    double
    constraint(const dealii::Tensor<2, d> &F) const
    {
      return determinant(F) - 1.;
    }

    /// The Cauchy stress sigma = J^-1 P F^T (in-plane part for d = 2).
    dealii::SymmetricTensor<2, d>
    cauchy(const dealii::Tensor<2, d> &F, const double q) const
    {
      return dealii::symmetrize(piola(F, q) * transpose(F)) / determinant(F);
    }

    /// I1 of the 3x3 right Cauchy-Green tensor (C33 = 1 for d = 2).
    static double
    first_invariant(const dealii::Tensor<2, d> &F)
    {
      return scalar_product(F, F) + (3. - d);
    }

    /// cof F = J F^-T.
    static dealii::Tensor<2, d>
    cofactor(const dealii::Tensor<2, d> &F)
    {
      return determinant(F) * transpose(invert(F));
    }

    /// d(cof F)[dF] = J tr(F^-1 dF) F^-T - J F^-T dF^T F^-T.
    static dealii::Tensor<2, d>
    cofactor_derivative(const dealii::Tensor<2, d> &F,
                        const dealii::Tensor<2, d> &dF)
    {
      const dealii::Tensor<2, d> F_inv_T = transpose(invert(F));
      const double               J       = determinant(F);
      return J * (trace(invert(F) * dF) * F_inv_T -
                  F_inv_T * transpose(dF) * F_inv_T);
    }

    double
    shear_modulus() const
    {
      return 2. * (C1 + C2);
    }

  private:
    const double C1;
    const double C2;
    /// Makes the undeformed state stress free at q = 0.
    const double q_ref;
  };
} // namespace rollnip

#endif
