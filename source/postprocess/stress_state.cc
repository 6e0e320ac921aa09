#include <rollnip/postprocess/stress_state.h>

#include <cmath>

namespace rollnip
{
  void
  polar_components(const SymmetricTensor<2, dim> &s,
                   const double                   phi,
                   double                        &rr,
                   double                        &tt,
                   double                        &rt)
  {
    const double c = std::cos(phi), sn = std::sin(phi);
    rr = c * c * s[0][0] + 2 * c * sn * s[0][1] + sn * sn * s[1][1];
    tt = sn * sn * s[0][0] - 2 * c * sn * s[0][1] + c * c * s[1][1];
    rt = (s[1][1] - s[0][0]) * c * sn + (c * c - sn * sn) * s[0][1];
  }

  namespace
  {
    StressState
    stress_state_of(const MaterialLaw<dim> &law,
                    const bool              linear,
                    const Tensor<2, dim>   &grad_u,
                    const double            q,
                    const Point<dim>       &X,
                    const Tensor<1, dim>   &u);
  } // namespace

  StressState
  evaluate_stress_state(const MaterialTable     &materials,
                        const types::material_id id,
                        const Tensor<2, dim>    &grad_u,
                        const double             q,
                        const Point<dim>        &X,
                        const Tensor<1, dim>    &u)
  {
    return stress_state_of(
      materials[id], materials.is_linear(), grad_u, q, X, u);
  }

  StressState
  evaluate_stress_state(const MaterialTable          &materials,
                        const CellAccessor<dim, dim> &cell,
                        const Tensor<2, dim>         &grad_u,
                        const double                  q,
                        const Point<dim>             &X,
                        const Tensor<1, dim>         &u)
  {
    return stress_state_of(
      materials.law(cell), materials.is_linear(), grad_u, q, X, u);
  }

  namespace
  {
    StressState
    stress_state_of(const MaterialLaw<dim> &law,
                    const bool              linear,
                    const Tensor<2, dim>   &grad_u,
                    const double            q,
                    const Point<dim>       &X,
                    const Tensor<1, dim>   &u)
    {
      StressState          s;
      const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + grad_u;
      s.sigma                = law.cauchy(F, q);
      s.sigma_zz             = law.out_of_plane_stress(F, q);
      const Point<dim> x     = X + u;
      polar_components(
        s.sigma, std::atan2(x[1], x[0]), s.sigma_rr, s.sigma_tt, s.sigma_rt);
      s.J = determinant(F);
      // In linear theory the stretches are those of the small strain.
      const SymmetricTensor<2, dim> C =
        linear ? unit_symmetric_tensor<dim>() + 2. * symmetrize(grad_u)
               : SymmetricTensor<2, dim>(symmetrize(transpose(F) * F));
      const auto ev    = eigenvalues(C);
      s.max_stretch    = std::sqrt(std::max(ev[0], 0.));
      s.min_stretch    = std::sqrt(std::max(ev[1], 0.));
      const double d11 = s.sigma[0][0] - s.sigma[1][1];
      const double d22 = s.sigma[1][1] - s.sigma_zz;
      const double d33 = s.sigma_zz - s.sigma[0][0];
      s.von_mises      = std::sqrt(0.5 * (d11 * d11 + d22 * d22 + d33 * d33) +
                              3. * s.sigma[0][1] * s.sigma[0][1]);
      s.hydrostatic_pressure = -(trace(s.sigma) + s.sigma_zz) / 3.;
      return s;
    }
  } // namespace
} // namespace rollnip
