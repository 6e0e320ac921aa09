#include <rollnip/output/stale_nip_directories.h>
#include <rollnip/run_errors.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace rollnip
{
  namespace
  {
    /// NN of a name nip-NN (two or more digits), or 0.
    unsigned long
    nip_number(const std::string &name)
    {
      const std::string prefix = "nip-";
      if (name.size() < prefix.size() + 2 || name.compare(0, 4, prefix) != 0 ||
          name.size() > prefix.size() + 9)
        return 0;
      const std::string digits = name.substr(prefix.size());
      if (!std::all_of(digits.begin(), digits.end(), [](const char c) {
            return std::isdigit(static_cast<unsigned char>(c));
          }))
        return 0;
      return std::stoul(digits);
    }
  } // namespace

  std::vector<std::string>
  remove_stale_nip_directories(const std::string &top,
                               const unsigned int n_nip_directories)
  {
    namespace fs = std::filesystem;
    std::vector<std::string> removed;
    std::error_code          error;
    if (!fs::is_directory(top, error))
      return removed;
    for (const auto &entry : fs::directory_iterator(top, error))
      {
        const std::string   name = entry.path().filename().string();
        const unsigned long n    = nip_number(name);
        if (n > n_nip_directories && entry.is_directory(error))
          removed.push_back(name);
      }
    std::sort(removed.begin(), removed.end());
    for (const auto &name : removed)
      {
        fs::remove_all(fs::path(top) / name, error);
        if (error)
          local_failure("cannot remove '" + top + "/" + name +
                        "', left by an earlier run: " + error.message());
      }
    return removed;
  }
} // namespace rollnip
