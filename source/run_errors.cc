#include <rollnip/run_errors.h>

#include <cctype>
#include <iostream>

namespace rollnip
{
  std::string
  one_line_message(const std::exception &e)
  {
    std::string       text   = e.what();
    const std::string marker = "Additional information:";
    const auto        begin  = text.find(marker);
    if (begin != std::string::npos)
      {
        text = text.substr(begin + marker.size());
        for (const char *end_marker : {"Stacktrace:", "--------"})
          {
            const auto end = text.find(end_marker);
            if (end != std::string::npos)
              text = text.substr(0, end);
          }
      }
    std::string line;
    bool        blank = false;
    for (const char c : text)
      if (std::isspace(static_cast<unsigned char>(c)))
        blank = true;
      else
        {
          if (blank && !line.empty())
            line += ' ';
          line += c;
          blank = false;
        }
    return line;
  }

  int
  run_guarded(const bool root, const std::function<int()> &body)
  {
    try
      {
        return body();
      }
    catch (const std::exception &e)
      {
        if (root)
          std::cerr << "rollnip: error: " << one_line_message(e) << std::endl;
        return 1;
      }
    catch (...)
      {
        if (root)
          std::cerr << "rollnip: error: unknown exception" << std::endl;
        return 1;
      }
  }
} // namespace rollnip
