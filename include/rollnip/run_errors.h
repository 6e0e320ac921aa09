#ifndef rollnip_run_errors_h
#define rollnip_run_errors_h

#include <exception>
#include <functional>
#include <stdexcept>
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
   * An error that one process may meet alone (rank 0's file output): the
   * others may be waiting in a collective call.
   */
  class LocalError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * An error met by this process alone (rank 0's files): with more than
   * one process it is printed here and ends all of them at once, before
   * any destructor could wait in a collective call; alone, it throws a
   * LocalError.
   */
  [[noreturn]] void
  local_failure(const std::string &message);

  /// Whether @p e may have been met by this process alone: a LocalError,
  /// a file-system error or an allocation failure.
  bool
  is_local_error(const std::exception &e);

  /**
   * Runs @p body and turns any exception into "rollnip: error: ..." on
   * standard error and exit code 1. Most errors are met by every process
   * alike (the input, a refused nip): rank 0 speaks and all return. A
   * local error (is_local_error()) with more than one process is printed
   * by the process that met it, which then ends all of them (MPI_Abort),
   * so that a run never hangs.
   */
  int
  run_guarded(const bool root, const std::function<int()> &body);

  /// For a handler that carries on after an error (the refinement study):
  /// rethrows @p e if it is local and there is more than one process.
  void
  rethrow_if_local(const std::exception &e);
} // namespace rollnip

#endif
