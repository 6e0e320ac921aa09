#ifndef rollnip_material_mooney_rivlin_law_h
#define rollnip_material_mooney_rivlin_law_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <rollnip/kinematics.h>
#include <rollnip/material/material_law.h>

#include <cmath>
#include <limits>

namespace rollnip
{
  /**
   * The incompressible Mooney-Rivlin law of doc/intro.md, section 2, in
   * finite strain, for a deformation gradient of any dimension d: d = 3 is
   * the full law of the 3D body, d = 2 the plane-strain law (F33 = 1). One
   * formula serves both:
   *   W = C1 (I1 - 3) + C2 (I2 - 3) + (q - q_ref) (J - 1),
   *   P = 2 C1 F + 2 C2 (I1 F - F C) + (q - q_ref) cof F,   q_ref = 2 C1 + 4 C2
   * (eq. 2.3) with I1 the trace of the 3x3 right Cauchy-Green tensor, i.e.
   * tr C + (3 - d). q_ref makes the undeformed state stress free at q = 0,
   * so that q is the mean stress of a purely hydrostatic state (positive in
   * tension); the paper's multiplier is p_Batra = q - q_ref. The test
   * mooney_rivlin_3d checks the 3D law at a plane-strain F against the 2D
   * one and against an independent plane-strain code.
   *
   * With a finite bulk modulus K the law is compressible: the constraint
   * becomes J - 1 - q/kappa, i.e. the stored energy gains
   *   -q_ref (J - 1) + kappa/2 (J - 1)^2,
   * and kappa = K - 2 G/3 + 2 C1 makes the small-strain law Hooke's law
   * with shear modulus G and bulk modulus K (the term 2 C1 offsets the
   * volumetric stiffness -2 C1 tr(eps) of the Mooney-Rivlin part).
   */
  template <int d>
  class MooneyRivlinLaw final : public MaterialLaw<d>
  {
  public:
    /// The law with constants @p C1, @p C2 [MPa] and bulk modulus
    /// @p bulk_modulus [MPa] (infinity: incompressible).
    MooneyRivlinLaw(
      const double C1,
      const double C2,
      const double bulk_modulus = std::numeric_limits<double>::infinity())
        : C1(C1)
        , C2(C2)
        , q_ref(2. * C1 + 4. * C2)
        , compliance(std::isinf(bulk_modulus)
                       ? 0.
                       : 1. / (bulk_modulus - 4. / 3. * (C1 + C2) + 2. * C1))
    {}

    /// First Piola-Kirchhoff stress (eq. 2.3).
    dealii::Tensor<2, d>
    piola(const dealii::Tensor<2, d> &F, const double q) const override
    {
      const dealii::Tensor<2, d> C  = transpose(F) * F;
      const double               I1 = trace(C) + (3. - d);
      return 2. * C1 * F + 2. * C2 * (I1 * F - F * C) +
             (q - q_ref) * cofactor(F);
    }

    /// dP[dF] at fixed q: d(I1) = 2 F:dF, d(F C) = dF C + F dC.
    dealii::Tensor<2, d>
    piola_derivative(const dealii::Tensor<2, d> &F,
                     const double                q,
                     const dealii::Tensor<2, d> &dF) const override
    {
      const dealii::Tensor<2, d> C   = transpose(F) * F;
      const double               I1  = trace(C) + (3. - d);
      const double               dI1 = 2. * scalar_product(F, dF);
      const dealii::Tensor<2, d> dC  = transpose(dF) * F + transpose(F) * dF;
      return 2. * C1 * dF + 2. * C2 * (dI1 * F + I1 * dF - dF * C - F * dC) +
             (q - q_ref) * cofactor_derivative(F, dF);
    }

    /// dP/dq = d(J - 1)/dF = cof F.
    dealii::Tensor<2, d>
    pressure_direction(const dealii::Tensor<2, d> &F) const override
    {
      return cofactor(F);
    }

    /// The incompressibility residual J - 1.
    double
    constraint(const dealii::Tensor<2, d> &F) const override
    {
      return determinant(F) - 1.;
    }

    /// The Cauchy stress sigma = J^-1 P F^T (in-plane part for d = 2).
    dealii::SymmetricTensor<2, d>
    cauchy(const dealii::Tensor<2, d> &F, const double q) const override
    {
      return dealii::symmetrize(piola(F, q) * transpose(F)) / determinant(F);
    }

    /// For d = 2: sigma_zz = J^-1 S_33 with S_33 = 2 C1 + 2 C2 (I1 - 1) +
    /// (q - q_ref) J (eq. 2.4); for d = 3: sigma_33.
    double
    out_of_plane_stress(const dealii::Tensor<2, d> &F,
                        const double                q) const override
    {
      if constexpr (d == 2)
        {
          const double J = determinant(F);
          return (2. * C1 + 2. * C2 * (first_invariant(F) - 1.) +
                  (q - q_ref) * J) /
                 J;
        }
      else
        return cauchy(F, q)[d - 1][d - 1];
    }

    double
    shear_modulus() const override
    {
      return 2. * (C1 + C2);
    }

    /// 1/kappa with kappa = K - 2 G/3 + 2 C1; zero when incompressible.
    double
    pressure_compliance() const override
    {
      return compliance;
    }

    /// I1 of the 3x3 right Cauchy-Green tensor (C33 = 1 for d = 2).
    static double
    first_invariant(const dealii::Tensor<2, d> &F)
    {
      return scalar_product(F, F) + (3. - d);
    }

    /// cof F = J F^-T (rollnip::cofactor).
    static dealii::Tensor<2, d>
    cofactor(const dealii::Tensor<2, d> &F)
    {
      return rollnip::cofactor(F);
    }

    /// d(cof F)[dF] (rollnip::cofactor_derivative).
    static dealii::Tensor<2, d>
    cofactor_derivative(const dealii::Tensor<2, d> &F,
                        const dealii::Tensor<2, d> &dF)
    {
      return rollnip::cofactor_derivative(F, dF);
    }

  private:
    const double C1;
    const double C2;
    const double q_ref;
    const double compliance;
  };
} // namespace rollnip

#endif
