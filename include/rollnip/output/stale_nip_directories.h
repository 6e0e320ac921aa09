#ifndef rollnip_output_stale_nip_directories_h
#define rollnip_output_stale_nip_directories_h

#include <string>
#include <vector>

namespace rollnip
{
  /**
   * Removes the nip-NN directories that an earlier sweep with more nips
   * left in @p top beyond the @p n_nip_directories of this run (0 for a
   * single nip, which writes to @p top itself): read beside the new
   * results they would pass for nips of this run. Returns the names it
   * removed, sorted; a directory it cannot remove is a local_failure().
   * Only nip-NN (two or more digits) directly in @p top is touched.
   */
  std::vector<std::string>
  remove_stale_nip_directories(const std::string &top,
                               unsigned int       n_nip_directories);
} // namespace rollnip

#endif
