#include <rollnip/material/viscoelastic_law.h>

#include <cmath>

namespace rollnip
{
  namespace
  {
    /// (1 - e^-x)/x, 1 at x = 0.
    double
    step_factor(const double x)
    {
      return x > 0 ? -std::expm1(-x) / x : 1.;
    }

    /// The d x d block of a 3x3 tensor.
    template <int d>
    dealii::Tensor<2, d>
    block(const dealii::Tensor<2, 3> &A)
    {
      dealii::Tensor<2, d> b;
      for (unsigned int i = 0; i < d; ++i)
        for (unsigned int j = 0; j < d; ++j)
          b[i][j] = A[i][j];
      return b;
    }
  } // namespace

  template <int d>
  ViscoelasticLaw<d>::ViscoelasticLaw(const double                  C1,
                                      const double                  C2,
                                      const std::vector<PronyTerm> &terms)
      : WrappingLaw<d>(elastic)
      , elastic(C1, C2)
      , C1(C1)
      , C2(C2)
      , terms(terms)
      , Q(terms.size())
      , S_dev(deviatoric_stress(dealii::unit_symmetric_tensor<3>()))
      , F_committed(dealii::unit_symmetric_tensor<3>())
      , F_trial(F_committed)
  {
    set_time_increment(0.);
  }

  template <int d>
  void
  ViscoelasticLaw<d>::set_time_increment(const double time_increment)
  {
    dt      = time_increment;
    beta    = 0;
    history = 0;
    for (unsigned int i = 0; i < terms.size(); ++i)
      {
        const double x = dt / terms[i].tau;
        beta += terms[i].g * step_factor(x);
        history += std::exp(-x) * Q[i];
      }
    history -= beta * S_dev;
  }

  template <int d>
  typename ViscoelasticLaw<d>::Tensor3
  ViscoelasticLaw<d>::embed(const dealii::Tensor<2, d> &A, const double A33)
  {
    Tensor3 T;
    for (unsigned int i = 0; i < d; ++i)
      for (unsigned int j = 0; j < d; ++j)
        T[i][j] = A[i][j];
    if constexpr (d == 2)
      T[2][2] = A33;
    return T;
  }

  template <int d>
  typename ViscoelasticLaw<d>::Tensor3
  ViscoelasticLaw<d>::deviatoric_stress(const Tensor3 &F) const
  {
    const Tensor3 I    = dealii::unit_symmetric_tensor<3>();
    const Tensor3 C    = transpose(F) * F;
    const Tensor3 A    = 2. * C1 * I + 2. * C2 * (trace(C) * I - C);
    const Tensor3 Cinv = invert(C);
    return A - scalar_product(A, C) / 3. * Cinv;
  }

  template <int d>
  typename ViscoelasticLaw<d>::Tensor3
  ViscoelasticLaw<d>::deviatoric_stress_derivative(const Tensor3 &F,
                                                   const Tensor3 &dF) const
  {
    const Tensor3 I     = dealii::unit_symmetric_tensor<3>();
    const Tensor3 C     = transpose(F) * F;
    const Tensor3 dC    = transpose(dF) * F + transpose(F) * dF;
    const Tensor3 A     = 2. * C1 * I + 2. * C2 * (trace(C) * I - C);
    const Tensor3 dA    = 2. * C2 * (trace(dC) * I - dC);
    const Tensor3 Cinv  = invert(C);
    const Tensor3 dCinv = -Cinv * dC * Cinv;
    const double  dAC   = scalar_product(dA, C) + scalar_product(A, dC);
    return dA - (dAC * Cinv + scalar_product(A, C) * dCinv) / 3.;
  }

  template <int d>
  typename ViscoelasticLaw<d>::Tensor3
  ViscoelasticLaw<d>::overstress(const Tensor3 &F) const
  {
    F_trial = F;
    return history + beta * deviatoric_stress(F);
  }

  template <int d>
  dealii::Tensor<2, d>
  ViscoelasticLaw<d>::piola(const dealii::Tensor<2, d> &F, const double q) const
  {
    const Tensor3 F3 = embed(F, 1.);
    return elastic.piola(F, q) + block<d>(F3 * overstress(F3));
  }

  template <int d>
  dealii::Tensor<2, d>
  ViscoelasticLaw<d>::piola_derivative(const dealii::Tensor<2, d> &F,
                                       const double                q,
                                       const dealii::Tensor<2, d> &dF) const
  {
    const Tensor3 F3  = embed(F, 1.);
    const Tensor3 dF3 = embed(dF, 0.);
    return elastic.piola_derivative(F, q, dF) +
           block<d>(dF3 * overstress(F3) +
                    beta * F3 * deviatoric_stress_derivative(F3, dF3));
  }

  template <int d>
  dealii::SymmetricTensor<2, d>
  ViscoelasticLaw<d>::cauchy(const dealii::Tensor<2, d> &F,
                             const double                q) const
  {
    const Tensor3 F3 = embed(F, 1.);
    return elastic.cauchy(F, q) +
           dealii::symmetrize(block<d>(F3 * overstress(F3) * transpose(F3))) /
             determinant(F);
  }

  template <int d>
  double
  ViscoelasticLaw<d>::out_of_plane_stress(const dealii::Tensor<2, d> &F,
                                          const double                q) const
  {
    const Tensor3 F3 = embed(F, 1.);
    return elastic.out_of_plane_stress(F, q) +
           (F3 * overstress(F3) * transpose(F3))[2][2] / determinant(F);
  }

  template <int d>
  void
  ViscoelasticLaw<d>::commit()
  {
    const Tensor3 S_new = deviatoric_stress(F_trial);
    for (unsigned int i = 0; i < terms.size(); ++i)
      {
        const double x = dt / terms[i].tau;
        Q[i] =
          std::exp(-x) * Q[i] + terms[i].g * step_factor(x) * (S_new - S_dev);
      }
    S_dev       = S_new;
    F_committed = F_trial;
    set_time_increment(dt);
  }

  template <int d>
  void
  ViscoelasticLaw<d>::rollback()
  {
    F_trial = F_committed;
  }

  template class ViscoelasticLaw<2>;
  template class ViscoelasticLaw<3>;
} // namespace rollnip
