#ifndef rollnip_app_adaptive_grading_h
#define rollnip_app_adaptive_grading_h

#include <deal.II/base/mpi.h>

#include <rollnip/parameters.h>

namespace rollnip
{
  /**
   * Runs the scene of @p parameters (on the processes of
   * @p communicator) Mesh/Adaptive grading passes times
   * (pressure or the first contact value), each time re-cutting the coarse
   * circumferential cells by adapted_circumferential_steps(), and returns
   * the parameters with Mesh::circumferential_steps set to the result.
   * Without passes, or on a gmsh mesh, returns @p parameters unchanged.
   */
  Parameters::AllParameters
  adapt_grading(const Parameters::AllParameters &parameters,
                MPI_Comm                         communicator);
} // namespace rollnip

#endif
