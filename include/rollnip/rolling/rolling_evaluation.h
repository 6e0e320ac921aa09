#ifndef rollnip_rolling_rolling_evaluation_h
#define rollnip_rolling_rolling_evaluation_h

#include <rollnip/body/roll_body.h>
#include <rollnip/contact/contact_result.h>
#include <rollnip/rolling/first_order_loss.h>
#include <rollnip/rolling/rolling_numbers.h>
#include <rollnip/rolling/rolling_parameters.h>

#include <functional>
#include <string>
#include <vector>

namespace rollnip
{
  /// Where evaluate_rolling() writes, and which of its files.
  struct RollingOutput
  {
    std::string directory;
    bool        write_csv = true;
    bool        write_vtu = false;
  };

  /**
   * The rolling post-process of the converged nip @p nip of @p body
   * (collective): the circles' strain history, the first-order loss at
   * every speed of @p rolling, the cover's temperature for each; prints
   * the headline on rank 0, warns (one line) when V tau / b is not small,
   * and writes rolling_profile.csv (dissipation and temperature over the
   * cover's thickness) and rolling_speeds.csv to @p output's directory if
   * it asks for CSV, temperature.pvtu if for VTU. @p indenter_radius [mm]
   * (inf: flat) is for the linear estimate; 0: none. @p circle_factor as
   * for first_order_loss().
   */
  RollingNumbers
  evaluate_rolling(
    const RollBody                                    &body,
    const ContactResult                               &nip,
    const Parameters::Rolling                         &rolling,
    const double                                       indenter_radius,
    const RollingOutput                               &output,
    const std::function<double(double, unsigned int)> &circle_factor = {});

  /// The key = value lines of @p r for contact.txt and summary.txt.
  std::string
  rolling_lines(const RollingNumbers &r);
} // namespace rollnip

#endif
