#ifndef rollnip_rolling_mate_rolling_h
#define rollnip_rolling_mate_rolling_h

#include <rollnip/body/roll_body.h>
#include <rollnip/rolling/rolling_numbers.h>
#include <rollnip/rolling/rolling_parameters.h>

#include <string>

namespace rollnip
{
  /**
   * The first-order loss and the steady temperature of the covered mating
   * roll @p mate's cover in its converged nip (half-chord @p half_chord
   * [mm]), at the same surface speed as the roll, Rolling/Surface speed:
   * the roll's route (doc/rolling.md, sections 2 and 4) on the mate's own
   * circles, radius, layers and hysteresis @p mate_rolling. Collective.
   */
  MateRolling
  evaluate_mate_rolling(const RollBody            &mate,
                        const Parameters::Rolling &mate_rolling,
                        const double               half_chord);

  /// The key = value lines of the mating roll's loss for contact.txt and
  /// summary.txt, and the pair's total drive power (a rigid mate: no
  /// loss of its own).
  std::string
  mate_rolling_lines(const RollingNumbers &n);
} // namespace rollnip

#endif
