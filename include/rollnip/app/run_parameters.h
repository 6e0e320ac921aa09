#ifndef rollnip_app_run_parameters_h
#define rollnip_app_run_parameters_h

#include <rollnip/app/accuracy_target.h>
#include <rollnip/app/refinement_study.h>
#include <rollnip/face/face_parameters.h>
#include <rollnip/parameters.h>
#include <rollnip/rolling/rolling_parameters.h>
#include <rollnip/three_d/three_d_parameters.h>

#include <string>

namespace rollnip
{
  /**
   * Everything a parameter file asks of a run: the scene, and the
   * subsections of the runs built on it (the face, an accuracy target,
   * the nips a study covers, the rolling loss, 3D). The file is parsed
   * once, and each subsection is checked against the scene as
   * AllParameters::read() leaves it (layers in the bond-first order).
   */
  struct RunParameters
  {
    Parameters::AllParameters  scene;
    Parameters::Face           face;
    Parameters::AccuracyTarget accuracy;
    Parameters::StudyValues    study_values;
    Parameters::Rolling        rolling;
    Parameters::ThreeD         three_d;

    /// Reads and checks @p filename; throws with a one-line message that
    /// names the file or the entry.
    void
    read(const std::string &filename);
  };
} // namespace rollnip

#endif
