#ifndef rollnip_material_mooney_rivlin_h
#define rollnip_material_mooney_rivlin_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <rollnip/global.h>
#include <rollnip/parameters.h>

namespace rollnip
{
  /**
   * The incompressible Mooney-Rivlin cover in plane strain (doc/intro.md,
   * section 2), as a stateless evaluation: stresses and their derivatives
   * as functions of the in-plane deformation gradient F (2x2, F33 = 1) and
   * the pressure unknown q.
   *
   * The energy is W = C1 (I1 - 3) + C2 (I2 - 3) + (q - q_ref) (J - 1) with
   * I1, I2 the invariants of the 3x3 C and q_ref = 2 C1 + 4 C2, so that
   *   P = 2 C1 F + 2 C2 (I1 F - F C) + (q - q_ref) cof F        (eq. 2.3)
   * and sigma = q I in the undeformed state: q is the mean stress of a
   * purely hydrostatic state (positive in tension). The paper's multiplier
   * is p_Batra = q - q_ref. In 2D cof F = J F^-T is linear in F, which makes
   * the tangent of the pressure term a constant.
   *
   * With Theory = linear the law is sigma = G (grad u + grad u^T) + q I with
   * G = 2 (C1 + C2) and the constraint div u = 0 (eq. 2.5).
   */
  class MooneyRivlin
  {
  public:
    /// The law of the outer layer of @p material (the whole cover for one
    /// layer; MaterialTable holds every layer's).
    explicit MooneyRivlin(const Parameters::Material &material);

    /// The law with constants @p C1, @p C2 [MPa], in linear theory if
    /// @p linear_theory (one layer of a layered cover).
    MooneyRivlin(const double C1, const double C2, const bool linear_theory);

    /// First Piola-Kirchhoff stress (in-plane part).
    Tensor<2, dim>
    piola(const Tensor<2, dim> &F, const double q) const;

    /// dP[dF] at (F, q): the directional derivative along dF at fixed q.
    Tensor<2, dim>
    piola_derivative(const Tensor<2, dim> &F,
                     const double          q,
                     const Tensor<2, dim> &dF) const;

    /// d(P)/dq = d(constraint)/dF = cof F (nonlinear) or I (linear).
    Tensor<2, dim>
    pressure_direction(const Tensor<2, dim> &F) const;

    /// The incompressibility residual: J - 1 (nonlinear) or tr(F - I).
    double
    constraint(const Tensor<2, dim> &F) const;

    /// The full Cauchy stress, in-plane components and sigma_zz.
    void
    cauchy(const Tensor<2, dim>    &F,
           const double             q,
           SymmetricTensor<2, dim> &sigma,
           double                  &sigma_zz) const;

    bool
    is_linear() const
    {
      return linear;
    }

    double
    shear_modulus() const
    {
      return 2. * (C1 + C2);
    }

  private:
    const double C1;
    const double C2;
    const bool   linear;
    /// q_ref = 2 C1 + 4 C2 makes the undeformed state stress free at q = 0.
    const double q_ref;
  };

  /// cof F = J F^-T for a 2x2 tensor.
  inline Tensor<2, dim>
  cofactor(const Tensor<2, dim> &F)
  {
    Tensor<2, dim> c;
    c[0][0] = F[1][1];
    c[0][1] = -F[1][0];
    c[1][0] = -F[0][1];
    c[1][1] = F[0][0];
    return c;
  }
} // namespace rollnip

#endif
