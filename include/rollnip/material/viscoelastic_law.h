#ifndef rollnip_material_viscoelastic_law_h
#define rollnip_material_viscoelastic_law_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <rollnip/material/mooney_rivlin_law.h>
#include <rollnip/material/wrapping_law.h>

#include <vector>

namespace rollnip
{
  /// One Maxwell branch of a Prony series: modulus ratio g (to the
  /// long-term modulus) and relaxation time tau [s].
  struct PronyTerm
  {
    double g;
    double tau;
  };

  /**
   * A finite-strain viscoelastic cover at one material point: the
   * Mooney-Rivlin law as the long-term (fully relaxed) response plus a
   * Prony series of Maxwell branches on the deviatoric stress,
   *   S = S_MR(C, q) + sum_i Q_i,
   *   dQ_i/dt + Q_i/tau_i = g_i d(S_dev)/dt,   S_dev = DEV[S_e(C)],
   * with S_e = 2 C1 I + 2 C2 (I1 I - C) the elastic part without the
   * pressure and DEV[A] = A - (A:C)/3 C^-1 (3x3, C33 = 1 in plane strain),
   * so that the branches carry no pressure: the incompressibility stays
   * the pressure unknown's. At small strain S_dev = 2 G eps_dev, and a
   * branch is a Maxwell element of modulus g_i times the long-term one:
   * the standard linear solid for one term, E(t) = E (1 + g e^(-t/tau)).
   *
   * Over a time step dt the branches are integrated exactly for S_dev
   * linear in time:
   *   Q_i = e^(-x_i) Q_i^n + g_i (1 - e^(-x_i))/x_i (S_dev - S_dev^n),
   * x_i = dt/tau_i, from the committed Q_i^n, S_dev^n. The internal
   * variables belong to this one point (a body holds one law per
   * quadrature point): every evaluation is a trial at the committed state,
   * commit() accepts the state of the last evaluated F, rollback() drops
   * it. With every g_i = 0 the law is the Mooney-Rivlin law exactly.
   */
  template <int d>
  class ViscoelasticLaw final : public WrappingLaw<d>
  {
  public:
    /// The law over the Mooney-Rivlin constants @p C1, @p C2 [MPa], at
    /// rest (no history) in the reference state.
    ViscoelasticLaw(const double                  C1,
                    const double                  C2,
                    const std::vector<PronyTerm> &terms);

    /// The time step [s] that the next evaluations and commit() close.
    void
    set_time_increment(const double dt);

    dealii::Tensor<2, d>
    piola(const dealii::Tensor<2, d> &F, const double q) const override;

    dealii::Tensor<2, d>
    piola_derivative(const dealii::Tensor<2, d> &F,
                     const double                q,
                     const dealii::Tensor<2, d> &dF) const override;

    dealii::SymmetricTensor<2, d>
    cauchy(const dealii::Tensor<2, d> &F, const double q) const override;

    double
    out_of_plane_stress(const dealii::Tensor<2, d> &F,
                        const double                q) const override;

    /// The long-term G = 2 (C1 + C2) [MPa].
    double
    shear_modulus() const override
    {
      return elastic.shear_modulus();
    }

    void
    commit() override;

    void
    rollback() override;

  private:
    using Tensor3 = dealii::Tensor<2, 3>;

    /// F as a 3x3 tensor (F33 = 1 for d = 2).
    static Tensor3
    embed(const dealii::Tensor<2, d> &A, const double A33);

    /// DEV[S_e(C)] of the 3x3 F.
    Tensor3
    deviatoric_stress(const Tensor3 &F) const;

    /// dDEV[S_e][dF] at F.
    Tensor3
    deviatoric_stress_derivative(const Tensor3 &F, const Tensor3 &dF) const;

    /// sum_i Q_i at F: the trial overstress from the committed state. Also
    /// remembers F for commit().
    Tensor3
    overstress(const Tensor3 &F) const;

    const MooneyRivlinLaw<d> elastic;
    const double             C1, C2;
    std::vector<PronyTerm>   terms;

    /// Per step: sum_i e^(-x_i) Q_i^n - beta S_dev^n, and
    /// beta = sum_i g_i (1 - e^(-x_i))/x_i.
    Tensor3 history;
    double  beta = 0;
    double  dt   = 0;

    /// Committed: each branch's Q_i^n, S_dev^n and F.
    std::vector<Tensor3> Q;
    Tensor3              S_dev;
    Tensor3              F_committed;

    /// The F of the last evaluation (the trial state commit() accepts).
    mutable Tensor3 F_trial;
  };
} // namespace rollnip

#endif
