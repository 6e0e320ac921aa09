#ifndef rollnip_material_linear_elastic_law_h
#define rollnip_material_linear_elastic_law_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <rollnip/material/material_law.h>

#include <cmath>
#include <limits>

namespace rollnip
{
  /**
   * The law of the linear theory (Theory = linear, doc/intro.md, eq. 2.5):
   * small strain, incompressible, with the shear modulus G of the layer's
   * Mooney-Rivlin law:
   *   sigma = G (grad u + grad u^T) + q I,   div u = 0,
   * written with F = I + grad u so that the assembly treats both theories
   * alike. Reference and current configuration coincide, so P = sigma and
   * the constraint tr(F - I) is linear. With a finite bulk modulus K the
   * constraint is div u - q/lambda, lambda = K - 2 G/3 (Hooke's law:
   * sigma = 2 G eps + lambda tr(eps) I); lambda must then be positive.
   */
  template <int d>
  class LinearElasticLaw final : public MaterialLaw<d>
  {
  public:
    /// The law of shear modulus @p G [MPa] and bulk modulus
    /// @p bulk_modulus [MPa] (infinity: incompressible).
    explicit LinearElasticLaw(
      const double G,
      const double bulk_modulus = std::numeric_limits<double>::infinity())
        : G(G)
        , compliance(
            std::isinf(bulk_modulus) ? 0. : 1. / (bulk_modulus - 2. / 3. * G))
    {}

    dealii::Tensor<2, d>
    piola(const dealii::Tensor<2, d> &F, const double q) const override
    {
      const dealii::Tensor<2, d> I      = dealii::unit_symmetric_tensor<d>();
      const dealii::Tensor<2, d> grad_u = F - I;
      return G * (grad_u + transpose(grad_u)) + q * I;
    }

    dealii::Tensor<2, d>
    piola_derivative(const dealii::Tensor<2, d> &,
                     const double,
                     const dealii::Tensor<2, d> &dF) const override
    {
      return G * (dF + transpose(dF));
    }

    /// d(tr(F - I))/dF = I.
    dealii::Tensor<2, d>
    pressure_direction(const dealii::Tensor<2, d> &) const override
    {
      return dealii::unit_symmetric_tensor<d>();
    }

    /// div u = tr(F - I).
    double
    constraint(const dealii::Tensor<2, d> &F) const override
    {
      return trace(F) - d;
    }

    dealii::SymmetricTensor<2, d>
    cauchy(const dealii::Tensor<2, d> &F, const double q) const override
    {
      return dealii::symmetrize(piola(F, q));
    }

    /// For d = 2: sigma_zz = q, since eps_zz = 0 (and lambda tr eps = q).
    double
    out_of_plane_stress(const dealii::Tensor<2, d> &F,
                        const double                q) const override
    {
      if constexpr (d == 2)
        return q;
      else
        return cauchy(F, q)[d - 1][d - 1];
    }

    double
    shear_modulus() const override
    {
      return G;
    }

    /// 1/lambda; zero when incompressible.
    double
    pressure_compliance() const override
    {
      return compliance;
    }

  private:
    const double G;
    const double compliance;
  };
} // namespace rollnip

#endif
