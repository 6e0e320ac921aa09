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

  /**
   * The line a signal prints at once, as "rollnip: error: @p prefix
   * interrupted by SIGINT@p suffix": mpirun follows the SIGTERM it sends
   * with SIGKILL a second later, too soon for the run to reach its next
   * load step and say where it stopped. Empty @p prefix and @p suffix
   * disarm it. Call it on one process only (rank 0).
   */
  void
  arm_interrupt_line(const std::string &prefix, const std::string &suffix);

  /// Whether a signal has printed the armed line on this process (the run
  /// then does not print it again).
  bool
  interrupt_line_printed();
} // namespace rollnip

#endif
