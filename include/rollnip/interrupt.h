#ifndef rollnip_interrupt_h
#define rollnip_interrupt_h

#include <mpi.h>

#include <string>

namespace rollnip
{
  /// From now on SIGINT and SIGTERM ask the run to stop at the next load
  /// step or nip instead of killing it, so that what has converged is
  /// written whole (a second signal kills as usual).
  void
  install_interrupt_handlers();

  /// Whether a stop was asked for on any process of @p communicator
  /// (collective, so that all processes stop at the same place).
  bool
  interrupt_requested(const MPI_Comm communicator);

  /// "interrupted by SIGINT" (or SIGTERM).
  std::string
  interrupt_message();
} // namespace rollnip

#endif
