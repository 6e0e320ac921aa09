#include <rollnip/output/report_stream.h>

namespace rollnip
{
  namespace
  {
    /// The screen while a QuietRun lives, else null.
    std::ostream *quiet_screen = nullptr;
  } // namespace

  std::ostream &
  report_stream()
  {
    return quiet_screen ? *quiet_screen : std::cout;
  }

  QuietRun::QuietRun(const bool quiet)
  {
    if (!quiet)
      return;
    screen       = std::make_unique<std::ostream>(std::cout.rdbuf());
    quiet_screen = screen.get();
    silence      = std::make_unique<SilenceStream>(std::cout);
  }

  QuietRun::~QuietRun()
  {
    if (screen)
      quiet_screen = nullptr;
  }
} // namespace rollnip
