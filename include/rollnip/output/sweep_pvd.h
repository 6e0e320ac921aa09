#ifndef rollnip_output_sweep_pvd_h
#define rollnip_output_sweep_pvd_h

#include <string>
#include <vector>

namespace rollnip
{
  /**
   * One ParaView collection (.pvd) for a whole sweep of nips: each nip's
   * final .pvtu as one dataset, with the sweep's control value (theta0,
   * the line load or the indentation) as its time, so that ParaView's time
   * slider steps through the sweep. What the time means is written into
   * the file as a comment.
   */
  class SweepPvd
  {
  public:
    /// @p filename (rank 0 writes it), @p time_meaning e.g.
    /// "line load P [N/mm]".
    SweepPvd(const std::string &filename, const std::string &time_meaning);

    /// Adds the dataset @p file (relative to the .pvd) at @p time as
    /// piece @p part (0: the roll, 1: a covered mating roll) and rewrites
    /// the file whole, so that a stopped sweep keeps its nips.
    void
    add(const double       time,
        const std::string &file,
        const unsigned int part = 0);

  private:
    struct Record
    {
      double       time;
      unsigned int part;
      std::string  file;
    };
    const std::string   filename;
    const std::string   time_meaning;
    std::vector<Record> records;
  };
} // namespace rollnip

#endif
