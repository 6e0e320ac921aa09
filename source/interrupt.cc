#include <deal.II/base/mpi.h>

#include <rollnip/interrupt.h>

#include <csignal>

namespace rollnip
{
  namespace
  {
    volatile std::sig_atomic_t received = 0;

    extern "C" void
    handle_stop(const int signal)
    {
      received = signal;
      // A second signal ends the process at once.
      std::signal(signal, SIG_DFL);
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
} // namespace rollnip
