#ifndef rollnip_rolling_first_order_loss_h
#define rollnip_rolling_first_order_loss_h

#include <rollnip/rolling/cover_circles.h>
#include <rollnip/rolling/rolling_parameters.h>

#include <functional>
#include <vector>

namespace rollnip
{
  /// The dissipation on one material circle (doc/rolling.md, eq. R.4).
  struct CircleLoss
  {
    double       radius; ///< [mm]
    double       weight; ///< radial quadrature weight [mm^2 per rad]
    unsigned int layer;
    double       mean; ///< dissipation density averaged over a turn [W/m^3]
    double       peak; ///< its largest value along the circle [W/m^3]
  };

  /// The hysteresis loss of the cover in steady rolling, to first order in
  /// Omega tau, at one surface speed.
  struct RollingLoss
  {
    double speed              = 0; ///< surface speed V [m/s]
    double power              = 0; ///< dissipated = drive power [W/m of face]
    double rolling_resistance = 0; ///< F_r = power / V [N/mm]
    std::vector<CircleLoss> circles;
  };

  /**
   * The first-order loss of the elastic nip on @p circles of a cover of
   * outer radius @p R0 [mm] turning at surface speed @p speed [m/s], whose
   * layers' hysteresis is @p rolling's: with Omega = V / R0 and ' = d/dtheta
   * along a circle,
   *   D = Omega^2 sum_i g_i tau_i S_iso' : E',
   * S_iso and E interpolated linearly in theta between the samples,
   * integrated over the whole turn (the model's half mirrored about the
   * line of centres, a half-roll sector closed across theta = 180 deg; on
   * a smaller sector the cover beyond it is taken as unstrained). The
   * power is the area integral of D over the cross-section. A
   * @p circle_factor(r, layer), if given, multiplies the loss of each
   * circle (a cover whose modulus and times vary with its temperature).
   */
  RollingLoss
  first_order_loss(
    const std::vector<MaterialCircle>                 &circles,
    const Parameters::Rolling                         &rolling,
    const double                                       R0,
    const double                                       sector_angle,
    const double                                       speed,
    const std::function<double(double, unsigned int)> &circle_factor = {});
} // namespace rollnip

#endif
