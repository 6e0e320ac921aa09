#ifndef rollnip_postprocess_stress_state_h
#define rollnip_postprocess_stress_state_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <rollnip/material/mooney_rivlin.h>

namespace rollnip
{
  /**
   * Everything reported about the stress and strain at one material point:
   * Cauchy stress in Cartesian and polar components, where the polar frame
   * is that of the CURRENT position x = X + u about the roll axis.
   */
  struct StressState
  {
    SymmetricTensor<2, dim> sigma; ///< in-plane Cauchy stress [MPa]
    double                  sigma_zz;
    double                  sigma_rr, sigma_tt, sigma_rt;
    double                  J;
    double                  max_stretch, min_stretch; ///< in-plane principal
    double                  von_mises;
    /// -tr(sigma)/3, positive in compression [MPa]
    double hydrostatic_pressure;
  };

  StressState
  evaluate_stress_state(const MooneyRivlin   &material,
                        const Tensor<2, dim> &grad_u,
                        const double          q,
                        const Point<dim>     &X,
                        const Tensor<1, dim> &u);

  /// Polar components (rr, tt, rt) of a symmetric tensor at angle phi.
  void
  polar_components(const SymmetricTensor<2, dim> &s,
                   const double                   phi,
                   double                        &rr,
                   double                        &tt,
                   double                        &rt);
} // namespace rollnip

#endif
