#ifndef rollnip_run_errors_h
#define rollnip_run_errors_h

#include <exception>
#include <functional>
#include <string>

namespace rollnip
{
  /**
   * The one-line form of an exception's message: for deal.II exceptions
   * the "Additional information" part (what a user can act on), with line
   * breaks and runs of blanks collapsed; else what() collapsed.
   */
  std::string
  one_line_message(const std::exception &e);

  /**
   * Runs @p body and turns any exception into "rollnip: error: ..." on
   * standard error and exit code 1. Until errors_may_be_local() is called,
   * every process meets the same errors (reading and checking the input),
   * so rank 0 speaks and all return. After it, one process may fail while
   * the others wait in a collective call: with more than one process the
   * failing one prints the message and ends all of them (MPI_Abort), so
   * that a run never hangs.
   */
  int
  run_guarded(const bool root, const std::function<int()> &body);

  /// From now on an error may be met by one process alone (see
  /// run_guarded()); called once the mesh is set up.
  void
  errors_may_be_local();
} // namespace rollnip

#endif
