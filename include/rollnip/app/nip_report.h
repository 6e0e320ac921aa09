#ifndef rollnip_app_nip_report_h
#define rollnip_app_nip_report_h

#include <deal.II/base/mpi.h>

#include <rollnip/app/nip_study.h>
#include <rollnip/parameters.h>
#include <rollnip/scene/scene_description.h>

#include <string>
#include <vector>

namespace rollnip
{
  /// The dwell time [ms] of a surface point in a nip of full width
  /// @p width [mm] at the surface speed @p speed [m/min] (> 0).
  double
  dwell_time_ms(double width, double speed);

  /**
   * The nip report (doc/engineering_inputs.md, section 4): per nip the
   * line load in Contact/Load unit, the full nip width 2b, u0, peak and
   * mean pressure, the dwell time at Contact/Surface speed and the modulus
   * used (of the rolls of @p scene), printed (if @p print) and written to
   * @p top/nip_report.csv by rank 0 of @p communicator.
   */
  void
  write_nip_report(const std::vector<NipRow>       &rows,
                   const Parameters::AllParameters &parameters,
                   const SceneDescription          &scene,
                   const std::string               &top,
                   MPI_Comm                         communicator,
                   bool                             print = true);
} // namespace rollnip

#endif
