#include <rollnip/global.h>
#include <rollnip/output/atomic_file.h>

#include <cstdio>
#include <fstream>

namespace rollnip
{
  void
  write_atomically(const std::string                         &path,
                   const std::function<void(std::ostream &)> &write)
  {
    const std::string tmp = path + ".part";
    {
      std::ofstream out(tmp);
      AssertThrow(out.good(),
                  ExcMessage("cannot open '" + tmp + "' for writing"));
      write(out);
      out.close();
      AssertThrow(!out.fail(), ExcMessage("writing '" + tmp + "' failed"));
    }
    AssertThrow(std::rename(tmp.c_str(), path.c_str()) == 0,
                ExcMessage("cannot rename '" + tmp + "' to '" + path + "'"));
  }
} // namespace rollnip
