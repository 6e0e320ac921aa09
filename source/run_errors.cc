#include <deal.II/base/mpi.h>

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

  namespace
  {
    bool local_errors = false;

    int
    report(const bool root, const std::string &message)
    {
      const unsigned int n =
        dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
      if (local_errors && n > 1)
        {
          std::cerr << "rollnip: error: " << message << " (on MPI process "
                    << dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD)
                    << " of " << n << "; ending all processes)" << std::endl;
          MPI_Abort(MPI_COMM_WORLD, 1);
        }
      if (root)
        std::cerr << "rollnip: error: " << message << std::endl;
      return 1;
    }
  } // namespace

  void
  errors_may_be_local()
  {
    local_errors = true;
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
        return report(root, one_line_message(e));
      }
    catch (...)
      {
        return report(root, "unknown exception");
      }
  }
} // namespace rollnip
