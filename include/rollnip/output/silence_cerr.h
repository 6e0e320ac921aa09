#ifndef rollnip_output_silence_cerr_h
#define rollnip_output_silence_cerr_h

#include <iostream>

namespace rollnip
{
  /// Discards what is written to a stream while the object lives.
  class SilenceStream
  {
  public:
    explicit SilenceStream(std::ostream &stream)
        : stream(stream)
        , format(nullptr)
        , saved(stream.rdbuf(nullptr))
    {
      format.copyfmt(stream);
    }
    /// Restores the stream and its format: the silenced writers may have
    /// set a width that no output consumed.
    ~SilenceStream()
    {
      stream.rdbuf(saved);
      stream.copyfmt(format);
    }
    SilenceStream(const SilenceStream &) = delete;
    SilenceStream &
    operator=(const SilenceStream &) = delete;

  private:
    std::ostream   &stream;
    std::ostream    format; ///< holds the stream's format, writes nothing
    std::streambuf *saved;
  };

  /**
   * Discards what libraries write to std::cerr while the object lives:
   * muparser's parse diagnostics and Amesos_Mumps' report of a workspace
   * retry read as failures, and rollnip says what matters in one line.
   */
  class SilenceCerr : public SilenceStream
  {
  public:
    SilenceCerr()
        : SilenceStream(std::cerr)
    {}
  };
} // namespace rollnip

#endif
