#ifndef rollnip_app_pressure_run_h
#define rollnip_app_pressure_run_h

#include <deal.II/base/mpi.h>

#include <rollnip/parameters.h>

#include <string>

namespace rollnip
{
  /// --validate: builds and checks the roll's mesh of @p parameters, read
  /// from @p file, and says the file is valid; nothing is solved. Returns
  /// the exit code.
  int
  validate_mesh(const Parameters::AllParameters &parameters,
                const std::string               &file,
                MPI_Comm                         communicator);

  /// The follower-pressure run (Contact/Mode = none) of the scene of
  /// @p parameters on the processes of @p communicator; returns the exit
  /// code.
  int
  run_pressure(const Parameters::AllParameters &parameters,
               MPI_Comm                         communicator);
} // namespace rollnip

#endif
