#ifndef rollnip_output_report_stream_h
#define rollnip_output_report_stream_h

#include <rollnip/output/silence_cerr.h>

#include <iostream>
#include <memory>

namespace rollnip
{
  /// Where the nip report is printed: std::cout, also while a QuietRun
  /// discards everything else written to it.
  std::ostream &
  report_stream();

  /**
   * Output/Verbosity = quiet: while the object lives (and @p quiet is
   * true), std::cout discards what the solvers write; report_stream()
   * still reaches the screen, and warnings and errors go to std::cerr.
   */
  class QuietRun
  {
  public:
    explicit QuietRun(bool quiet);
    ~QuietRun();
    QuietRun(const QuietRun &) = delete;
    QuietRun &
    operator=(const QuietRun &) = delete;

  private:
    std::unique_ptr<std::ostream>  screen; ///< std::cout's own buffer
    std::unique_ptr<SilenceStream> silence;
  };
} // namespace rollnip

#endif
