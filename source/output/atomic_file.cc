#include <rollnip/global.h>
#include <rollnip/output/atomic_file.h>
#include <rollnip/run_errors.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace rollnip
{
  void
  make_directories(const std::string &directory)
  {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error)
      local_failure("cannot create the output directory '" + directory +
                    "': " + error.message());
  }

  void
  write_atomically(const std::string                         &path,
                   const std::function<void(std::ostream &)> &write)
  {
    const std::string tmp = path + ".part";
    {
      std::ofstream out(tmp);
      if (!out.good())
        local_failure("cannot open '" + tmp + "' for writing");
      write(out);
      out.close();
      if (out.fail())
        local_failure("writing '" + tmp + "' failed");
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
      local_failure("cannot rename '" + tmp + "' to '" + path + "'");
  }
} // namespace rollnip
