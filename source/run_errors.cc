#include <deal.II/base/mpi.h>

#include <rollnip/run_errors.h>

#include <cctype>
#include <filesystem>
#include <iostream>
#include <new>

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

  bool
  is_local_error(const std::exception &e)
  {
    return dynamic_cast<const LocalError *>(&e) ||
           dynamic_cast<const std::filesystem::filesystem_error *>(&e) ||
           dynamic_cast<const std::bad_alloc *>(&e);
  }

  void
  local_failure(const std::string &message)
  {
    const unsigned int n =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    if (n > 1)
      {
        std::cerr << "rollnip: error: " << message << " (on MPI process "
                  << dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD)
                  << " of " << n << "; ending all processes)" << std::endl;
        MPI_Abort(MPI_COMM_WORLD, 1);
      }
    throw LocalError(message);
  }

  void
  rethrow_if_local(const std::exception &e)
  {
    if (is_local_error(e) &&
        dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      throw;
  }

  namespace
  {
    int
    report(const bool root, const std::string &message, const bool local)
    {
      const unsigned int n =
        dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
      if (local && n > 1)
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

  int
  run_guarded(const bool root, const std::function<int()> &body)
  {
    try
      {
        return body();
      }
    catch (const std::exception &e)
      {
        return report(root, one_line_message(e), is_local_error(e));
      }
    catch (...)
      {
        return report(root, "unknown exception", false);
      }
  }
} // namespace rollnip
