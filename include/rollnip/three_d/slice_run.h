#ifndef rollnip_three_d_slice_run_h
#define rollnip_three_d_slice_run_h

#include <rollnip/parameters.h>
#include <rollnip/three_d/three_d_parameters.h>

#include <mpi.h>

#include <string>

namespace rollnip
{
  /**
   * The 3D run (Three d/Enabled, doc/three_d.md): the slice of the scene
   * pressed to each approach of Contact/Values in turn, at the mesh level
   * Mesh/Global refinements. Writes slice_3d.csv (one row per approach),
   * summary.txt (the last approach, the DoFs and the time) and
   * slice_3d_NN.pvtu with one .vtu per process to Output/Directory;
   * returns the exit code.
   */
  int
  run_three_d(const Parameters::AllParameters &parameters,
              const Parameters::ThreeD        &three_d,
              MPI_Comm                         communicator);

  namespace three_d
  {
    /**
     * --validate on a 3D scene: builds the body's mesh at Mesh/Global
     * refinements (the cover, a gmsh cross-section or a drawn mesh with
     * their checks, the elastic core's tube), counts its DoFs and prints
     * them with "'@p file' is valid" on the root process; throws the
     * one-line message of the first check that fails.
     */
    int
    validate_slice_body(const Parameters::AllParameters &parameters,
                        const Parameters::ThreeD        &three_d,
                        const std::string               &file,
                        MPI_Comm                         communicator);
  } // namespace three_d
} // namespace rollnip

#endif
