#ifndef rollnip_app_face_run_h
#define rollnip_app_face_run_h

#include <deal.II/base/mpi.h>

#include <rollnip/face/face_parameters.h>
#include <rollnip/parameters.h>

namespace rollnip
{
  /**
   * The face model's run (doc/face.md): the nip along the roll face with
   * @p parameters as its cross-section and @p face as the rolls, crowns
   * and loading. Writes face.csv, summary.txt and, for a crowned roll,
   * off_design.csv to Output/Directory, on the processes of
   * @p communicator; returns the exit code.
   */
  int
  run_face(const Parameters::AllParameters &parameters,
           const Parameters::Face          &face,
           MPI_Comm                         communicator);
} // namespace rollnip

#endif
