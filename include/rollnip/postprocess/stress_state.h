#ifndef rollnip_postprocess_stress_state_h
#define rollnip_postprocess_stress_state_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <rollnip/global.h>
#include <rollnip/material/material_table.h>

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

  /// The state at a point of a cell of material id @p id (its layer's law
  /// in @p materials) with displacement gradient @p grad_u, pressure
  /// unknown @p q, reference position @p X and displacement @p u.
  StressState
  evaluate_stress_state(const MaterialTable     &materials,
                        const types::material_id id,
                        const Tensor<2, dim>    &grad_u,
                        const double             q,
                        const Point<dim>        &X,
                        const Tensor<1, dim>    &u);

  /// The same in @p cell, whose law is MaterialTable::law() (its layer's,
  /// scaled by the modulus factor if one is set).
  StressState
  evaluate_stress_state(const MaterialTable          &materials,
                        const CellAccessor<dim, dim> &cell,
                        const Tensor<2, dim>         &grad_u,
                        const double                  q,
                        const Point<dim>             &X,
                        const Tensor<1, dim>         &u);

  /// Polar components (rr, tt, rt) of a symmetric tensor at angle phi.
  void
  polar_components(const SymmetricTensor<2, dim> &s,
                   const double                   phi,
                   double                        &rr,
                   double                        &tt,
                   double                        &rt);
} // namespace rollnip

#endif
