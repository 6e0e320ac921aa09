#include <rollnip/material/mooney_rivlin.h>

namespace rollnip
{
  MooneyRivlin::MooneyRivlin(const Parameters::Material &material)
      : MooneyRivlin(material.layer_C1.back(),
                     material.layer_C2.back(),
                     material.theory == Parameters::Theory::linear)
  {}

  MooneyRivlin::MooneyRivlin(const double C1,
                             const double C2,
                             const bool   linear_theory)
      : C1(C1)
      , C2(C2)
      , linear(linear_theory)
      , q_ref(2. * C1 + 4. * C2)
  {}

  Tensor<2, dim>
  MooneyRivlin::piola(const Tensor<2, dim> &F, const double q) const
  {
    const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
    if (linear)
      {
        const Tensor<2, dim> grad_u = F - I;
        return shear_modulus() * (grad_u + transpose(grad_u)) + q * I;
      }
    // eq. 2.3, with I1 = tr C + 1 (C33 = 1).
    const Tensor<2, dim> C  = transpose(F) * F;
    const double         I1 = trace(C) + 1.;
    return 2. * C1 * F + 2. * C2 * (I1 * F - F * C) + (q - q_ref) * cofactor(F);
  }

  Tensor<2, dim>
  MooneyRivlin::piola_derivative(const Tensor<2, dim> &F,
                                 const double          q,
                                 const Tensor<2, dim> &dF) const
  {
    if (linear)
      return shear_modulus() * (dF + transpose(dF));
    // d(I1) = 2 F:dF;  d(F C) = dF C + F (dF^T F + F^T dF).
    const Tensor<2, dim> C   = transpose(F) * F;
    const double         I1  = trace(C) + 1.;
    const double         dI1 = 2. * scalar_product(F, dF);
    const Tensor<2, dim> dC  = transpose(dF) * F + transpose(F) * dF;
    return 2. * C1 * dF + 2. * C2 * (dI1 * F + I1 * dF - dF * C - F * dC) +
           (q - q_ref) * cofactor(dF);
  }

  Tensor<2, dim>
  MooneyRivlin::pressure_direction(const Tensor<2, dim> &F) const
  {
    if (linear)
      return unit_symmetric_tensor<dim>();
    return cofactor(F);
  }

  double
  MooneyRivlin::constraint(const Tensor<2, dim> &F) const
  {
    if (linear)
      return trace(F) - dim;
    return determinant(F) - 1.;
  }

  void
  MooneyRivlin::cauchy(const Tensor<2, dim>    &F,
                       const double             q,
                       SymmetricTensor<2, dim> &sigma,
                       double                  &sigma_zz) const
  {
    if (linear)
      {
        // Small strain: sigma_zz = q since eps_zz = 0 and tr eps = 0.
        sigma    = symmetrize(piola(F, q));
        sigma_zz = q;
        return;
      }
    // sigma = J^-1 P F^T; sigma_zz = J^-1 S_33 with
    // S_33 = 2 C1 + 2 C2 (I1 - 1) + (q - q_ref) J.
    const double J  = determinant(F);
    const double I1 = scalar_product(F, F) + 1.;
    sigma           = symmetrize(piola(F, q) * transpose(F)) / J;
    sigma_zz        = (2. * C1 + 2. * C2 * (I1 - 1.) + (q - q_ref) * J) / J;
  }
} // namespace rollnip
