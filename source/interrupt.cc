#include <deal.II/base/mpi.h>

#include <rollnip/interrupt.h>

#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstring>

namespace rollnip
{
  namespace
  {
    volatile std::sig_atomic_t received = 0;

    /// The armed line in two buffers: the handler reads the one @p armed
    /// names (0: none) while the other is rewritten, so that it never
    /// sees half a line.
    constexpr std::size_t      line_capacity = 1024;
    char                       lines[2][2][line_capacity];
    std::size_t                lengths[2][2];
    volatile std::sig_atomic_t armed   = 0;
    volatile std::sig_atomic_t printed = 0;

    extern "C" void
    handle_stop(const int signal)
    {
      received = signal;
      // A second signal ends the process at once.
      std::signal(signal, SIG_DFL);
      const int slot = armed;
      if (slot > 0 && !printed)
        {
          const int  which = signal == SIGTERM ? 1 : 0;
          const auto n     = ::write(STDERR_FILENO,
                                 lines[slot - 1][which],
                                 lengths[slot - 1][which]);
          (void)n;
          printed = 1;
        }
    }
  } // namespace

  void
  install_interrupt_handlers()
  {
    std::signal(SIGINT, handle_stop);
    std::signal(SIGTERM, handle_stop);
  }

  bool
  interrupt_requested(const MPI_Comm communicator)
  {
    return dealii::Utilities::MPI::max(received != 0 ? 1 : 0, communicator) !=
           0;
  }

  std::string
  interrupt_message()
  {
    return std::string("interrupted by ") +
           (received == SIGTERM ? "SIGTERM" : "SIGINT");
  }

  void
  arm_interrupt_line(const std::string &prefix, const std::string &suffix)
  {
    if (prefix.empty() && suffix.empty())
      {
        armed = 0;
        return;
      }
    const int slot = armed == 1 ? 2 : 1;
    for (const int which : {0, 1})
      {
        const std::string line = "rollnip: error: " + prefix +
                                 "interrupted by " +
                                 (which == 1 ? "SIGTERM" : "SIGINT") + suffix;
        const std::size_t n = std::min(line.size(), line_capacity - 1);
        std::memcpy(lines[slot - 1][which], line.data(), n);
        lines[slot - 1][which][n] = '\n';
        lengths[slot - 1][which]  = n + 1;
      }
    armed = slot;
  }

  bool
  interrupt_line_printed()
  {
    return printed != 0;
  }
} // namespace rollnip
