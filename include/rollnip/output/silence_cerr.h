#ifndef rollnip_output_silence_cerr_h
#define rollnip_output_silence_cerr_h

#include <iostream>

namespace rollnip
{
  /**
   * Discards what libraries write to std::cerr while the object lives:
   * muparser's parse diagnostics and Amesos_Mumps' report of a workspace
   * retry read as failures, and rollnip says what matters in one line.
   */
  class SilenceCerr
  {
  public:
    SilenceCerr()
        : saved(std::cerr.rdbuf(nullptr))
    {}
    ~SilenceCerr()
    {
      std::cerr.rdbuf(saved);
    }
    SilenceCerr(const SilenceCerr &) = delete;
    SilenceCerr &
    operator=(const SilenceCerr &) = delete;

  private:
    std::streambuf *saved;
  };
} // namespace rollnip

#endif
