#ifndef rollnip_material_material_law_h
#define rollnip_material_material_law_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace rollnip
{
  /**
   * What the mixed displacement-pressure (u, q) assembly and the output
   * need of a material law, and nothing more, for a deformation gradient F
   * of dimension d (d = 2: plane strain, F33 = 1). The residual is
   *   R_u = int P(F, q) : Grad v dV,   R_q = int w c(F) dV
   * with c the volume constraint, and its tangent needs dP[dF] at fixed q
   * and dP/dq = dc/dF. A compressible law is the perturbed-Lagrangian form
   *   c(F, q) = constraint(F) - pressure_compliance() q
   * (pressure_compliance() = 1/kappa, zero for an incompressible law), so
   * the pressure block of the tangent is -1/kappa M_p. Laws come from
   * make_layer_law() (material/law_factory.h), one per layer.
   *
   * A law with internal variables (a viscoelastic one) evaluates at its
   * last committed state. commit() and rollback() are the named points
   * where the solvers accept or discard what was evaluated since the last
   * commit: a converged load step commits, a failed Newton solve (and the
   * cut-back or predictor retry after it) rolls back. Elastic laws have
   * nothing to commit.
   */
  template <int d>
  class MaterialLaw
  {
  public:
    virtual ~MaterialLaw() = default;

    /// First Piola-Kirchhoff stress P(F, q) [MPa].
    virtual dealii::Tensor<2, d>
    piola(const dealii::Tensor<2, d> &F, const double q) const = 0;

    /// dP[dF] at (F, q): the directional derivative along dF at fixed q.
    virtual dealii::Tensor<2, d>
    piola_derivative(const dealii::Tensor<2, d> &F,
                     const double                q,
                     const dealii::Tensor<2, d> &dF) const = 0;

    /// dP/dq, equal to dc/dF: the coupling blocks of the tangent.
    virtual dealii::Tensor<2, d>
    pressure_direction(const dealii::Tensor<2, d> &F) const = 0;

    /// The kinematic part c(F) of the constraint residual (J - 1).
    virtual double
    constraint(const dealii::Tensor<2, d> &F) const = 0;

    /// -dc/dq = 1/kappa [1/MPa]: zero (the default) for an exactly
    /// incompressible law, positive for a compressible one.
    virtual double
    pressure_compliance() const
    {
      return 0;
    }

    /// The Cauchy stress [MPa] (its in-plane part for d = 2).
    virtual dealii::SymmetricTensor<2, d>
    cauchy(const dealii::Tensor<2, d> &F, const double q) const = 0;

    /// The Cauchy stress normal to the plane [MPa]: sigma_zz of the
    /// plane-strain state for d = 2, sigma_33 for d = 3.
    virtual double
    out_of_plane_stress(const dealii::Tensor<2, d> &F,
                        const double                q) const = 0;

    /// The small-strain shear modulus G [MPa]: it scales the pressure
    /// block of the preconditioner and the contact estimates.
    virtual double
    shear_modulus() const = 0;

    /// Accepts the internal variables of the last evaluations.
    virtual void
    commit()
    {}

    /// Returns the internal variables to the last commit.
    virtual void
    rollback()
    {}
  };
} // namespace rollnip

#endif
