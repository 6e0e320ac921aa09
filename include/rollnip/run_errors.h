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
   * standard error (rank 0 only) and exit code 1.
   */
  int
  run_guarded(const bool root, const std::function<int()> &body);
} // namespace rollnip

#endif
