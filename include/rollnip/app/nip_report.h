#ifndef rollnip_app_nip_report_h
#define rollnip_app_nip_report_h

#include <deal.II/base/mpi.h>

#include <rollnip/app/nip_study.h>
#include <rollnip/parameters.h>
#include <rollnip/scene/scene_description.h>

#include <limits>
#include <string>
#include <vector>

namespace rollnip
{
  /// The dwell time [ms] of a surface point in a nip of full width
  /// @p width [mm] at the surface speed @p speed [m/min] (> 0).
  double
  dwell_time_ms(double width, double speed);

  /// The nip widths 2b [mm] at the two ends of the hardness modulus band
  /// (Hardness::modulus_band), solved as the same nip at the loads
  /// P E / E_low and P E / E_high (exact for one material against a rigid
  /// mate: the solution at k G under P is that at G under P / k); nan when
  /// not solved.
  struct BandWidths
  {
    double at_low_modulus  = std::numeric_limits<double>::quiet_NaN();
    double at_high_modulus = std::numeric_limits<double>::quiet_NaN();
  };

  /// Whether the band widths of @p parameters' scene follow from the
  /// scaling of BandWidths: a load-controlled nip of one cover material
  /// whose modulus came from hardness, against a rigid mate.
  bool
  band_by_scaling(const Parameters::AllParameters &parameters);

  /// Warnings, one line each on std::cerr, for nip @p n of @p row where the
  /// material law or the hardness relation leave the range where they were
  /// validated (doc/engineering_inputs.md, "Guard rails").
  void
  warn_outside_validated_range(const NipRow           &row,
                               unsigned int            n,
                               const SceneDescription &scene);

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
                   const std::vector<BandWidths>   &band  = {},
                   bool                             print = true);
} // namespace rollnip

#endif
