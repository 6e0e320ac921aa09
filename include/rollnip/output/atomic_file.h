#ifndef rollnip_output_atomic_file_h
#define rollnip_output_atomic_file_h

#include <functional>
#include <ostream>
#include <string>

namespace rollnip
{
  /**
   * Writes a file whole or not at all: @p write fills a temporary file next
   * to @p path, which is renamed onto @p path only after it was flushed and
   * closed without error. A failure is local_failure() with the file name
   * (only rank 0 writes).
   */
  void
  write_atomically(const std::string                         &path,
                   const std::function<void(std::ostream &)> &write);

  /// std::filesystem::create_directories, with a failure turned into
  /// local_failure() naming the directory.
  void
  make_directories(const std::string &directory);
} // namespace rollnip

#endif
