#ifndef rollnip_rolling_steady_rolling_report_h
#define rollnip_rolling_steady_rolling_report_h

#include <rollnip/rolling/rolling_numbers.h>
#include <rollnip/rolling/steady_rolling_sweep.h>

#include <string>
#include <vector>

namespace rollnip
{
  /// The full steady rolling's numbers for the summary and the nip report
  /// from the sweep's @p rows: those of the row at @p surface_speed [m/s]
  /// (available only if it is a converged full speed) and the hottest
  /// converged row's speed and largest temperature.
  FullRolling
  full_rolling_numbers(const std::vector<SteadyRollingRow> &rows,
                       const double                         surface_speed);

  /// The key = value lines of @p n.full for contact.txt and summary.txt;
  /// empty if the full steady rolling did not run.
  std::string
  full_rolling_lines(const RollingNumbers &n);
} // namespace rollnip

#endif
