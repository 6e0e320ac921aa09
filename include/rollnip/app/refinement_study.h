#ifndef rollnip_app_refinement_study_h
#define rollnip_app_refinement_study_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <rollnip/parameters.h>

#include <limits>
#include <string>
#include <vector>

namespace rollnip
{
  /// Estimate of the converged value of a sequence of results on meshes
  /// refined by halving (doc/intro.md section 8).
  struct Extrapolation
  {
    double value = 0;     ///< Richardson-extrapolated, or the finest if none
    double order = 0;     ///< observed order from the last three levels
    bool   valid = false; ///< false: not monotone, or fewer than 3 levels
    /// The observed order was above @p max_order, so the value was
    /// extrapolated with max_order instead (an order no element reaches
    /// comes from a pre-asymptotic sequence, and would overstate the
    /// accuracy).
    bool capped = false;
  };

  /// From the last three values v1, v2, v3: with r = (v3 - v2)/(v2 - v1)
  /// in (0, 0.9), order = -log2 r and value = v3 + (v3 - v2) r / (1 - r),
  /// with r raised to 2^-max_order if the order is above @p max_order.
  Extrapolation
  extrapolate(const std::vector<double> &values,
              const double max_order = std::numeric_limits<double>::max());

  namespace Parameters
  {
    /// Study/Values: the nips of a contact sweep the refinement study
    /// runs; by default all of Contact/Values, so that the study answers
    /// for every load the user asked about, not only the first.
    struct StudyValues
    {
      /// In the program's units (theta0 [rad], P [N/mm], u0 [mm]); empty:
      /// every value of Contact/Values.
      std::vector<double> values;

      /// Declares Study/Values.
      static void
      declare(ParameterHandler &prm);
      /// The entry of @p prm, in the unit of Contact/Values of @p scene.
      void
      parse(ParameterHandler &prm, const AllParameters &scene);
    };
  } // namespace Parameters

  /**
   * The refinement study (Study subsection): the scene of @p parameters at
   * each of Study/Refinement levels, for each of Study/Elements; for a
   * contact scene, for each nip of @p nips (default: every value of
   * Contact/Values), said on the screen. Prints a deal.II ConvergenceTable
   * per nip and element and writes study.csv (with the nip and its
   * prescribed value) and study.txt in Output/Directory, each run's own
   * files below study/ (study/nip-NN/ for several nips). Returns the exit
   * code; a failed run ends the study with the rows before it written.
   */
  int
  run_refinement_study(const Parameters::AllParameters &parameters,
                       MPI_Comm                         communicator,
                       const Parameters::StudyValues   &nips = {});
} // namespace rollnip

#endif
