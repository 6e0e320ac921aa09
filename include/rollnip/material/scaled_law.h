#ifndef rollnip_material_scaled_law_h
#define rollnip_material_scaled_law_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <rollnip/material/wrapping_law.h>

namespace rollnip
{
  /**
   * A law whose every modulus is @p factor times that of @p base: the
   * cover where it is warmer or cooler than the temperature its law was
   * measured at (doc/rolling.md, the cover's softening). The pressure
   * unknown q enters every law of this program as (q - q_ref(G)) times
   * d c/dF with q_ref proportional to the moduli, so
   *   P_s(F, q) = s P(F, q / s)
   * is the law of the scaled moduli exactly (the Mooney-Rivlin law of
   * s C1, s C2; the linear law of s G), and dP_s/dq = dP/dq. With s = 1
   * every value is the base law's to the last bit.
   */
  template <int d>
  class ScaledLaw final : public WrappingLaw<d>
  {
  public:
    ScaledLaw(const MaterialLaw<d> &base, const double factor)
        : WrappingLaw<d>(base)
        , s(factor)
    {}

    dealii::Tensor<2, d>
    piola(const dealii::Tensor<2, d> &F, const double q) const override
    {
      return s == 1. ? this->wrapped.piola(F, q)
                     : s * this->wrapped.piola(F, q / s);
    }

    dealii::Tensor<2, d>
    piola_derivative(const dealii::Tensor<2, d> &F,
                     const double                q,
                     const dealii::Tensor<2, d> &dF) const override
    {
      return s == 1. ? this->wrapped.piola_derivative(F, q, dF)
                     : s * this->wrapped.piola_derivative(F, q / s, dF);
    }

    dealii::SymmetricTensor<2, d>
    cauchy(const dealii::Tensor<2, d> &F, const double q) const override
    {
      return s == 1. ? this->wrapped.cauchy(F, q)
                     : s * this->wrapped.cauchy(F, q / s);
    }

    double
    out_of_plane_stress(const dealii::Tensor<2, d> &F,
                        const double                q) const override
    {
      return s == 1. ? this->wrapped.out_of_plane_stress(F, q)
                     : s * this->wrapped.out_of_plane_stress(F, q / s);
    }

    double
    shear_modulus() const override
    {
      return s * this->wrapped.shear_modulus();
    }

    /// 1/(s kappa): the bulk modulus scales with the others.
    double
    pressure_compliance() const override
    {
      return this->wrapped.pressure_compliance() / s;
    }

    /// The factor on the base law's moduli.
    double
    factor() const
    {
      return s;
    }

  private:
    const double s;
  };
} // namespace rollnip

#endif
