#ifndef rollnip_rolling_thermal_fixed_point_h
#define rollnip_rolling_thermal_fixed_point_h

#include <rollnip/body/roll_body.h>
#include <rollnip/contact/contact_result.h>
#include <rollnip/rolling/rolling_numbers.h>
#include <rollnip/rolling/rolling_parameters.h>
#include <rollnip/rolling/thermal_softening.h>

#include <functional>
#include <string>

namespace rollnip
{
  /// The loss factor of a circle (radius [mm], layer) of the cover, as
  /// first_order_loss() takes it.
  using CircleFactor = std::function<double(double, unsigned int)>;

  /**
   * The nip of a cover that softens as it heats (doc/rolling.md): from
   * the converged constant-modulus nip @p nip of @p body, the fixed point
   *   nip -> first-order loss -> temperature T(r) -> modulus and times
   *   -> nip
   * at Rolling/Surface speed. Each pass gives every cell of the roll the
   * moduli exp(-c (T - T_ref)) times its layer's at the temperature of
   * its centre (MaterialTable::set_modulus_factor()) and solves the nip
   * again with @p resolve (from the last nip, at the same control value);
   * the loss of each circle is scaled by the same modulus factor at its
   * radius (the loss is linear in the moduli) and by the WLF shift a_T
   * (linear in the times). The next pass's temperature is relaxed by
   * Aitken's factor from the last two residuals. Stops when a pass's
   * temperature differs from the one its modulus was taken at by no more
   * than the tolerance at every node, or after Maximum iterations (then
   * @p coupling says so and a warning is printed). Returns the last nip; @p
   * coupling has the iteration's history and the constant-modulus answer, @p
   * circle_factor the loss factor the last nip was solved with, for
   * evaluate_rolling(). Collective; throws if a nip fails.
   */
  ContactResult
  soften_to_fixed_point(
    RollBody                                                  &body,
    const ContactResult                                       &nip,
    const Parameters::Rolling                                 &rolling,
    const std::function<ContactResult(const ContactResult &)> &resolve,
    ThermalCoupling                                           &coupling,
    CircleFactor                                              &circle_factor);
  /// The key = value lines of the fixed point for contact.txt and
  /// summary.txt, beside rolling_lines() (@p n the softened nip's); empty
  /// if the cover does not soften.
  std::string
  thermal_lines(const RollingNumbers &n);

} // namespace rollnip

#endif
