#include <rollnip/mpi_start.h>

#include <cstdlib>
#include <string>

namespace rollnip
{
  namespace
  {
    /// The rank a launcher gave this process, nullptr without one (Open
    /// MPI's mpirun, PMIx and PMI launchers such as srun).
    const char *
    launcher_rank()
    {
      for (const char *name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})
        if (const char *value = std::getenv(name))
          return value;
      return nullptr;
    }
  } // namespace

  bool
  is_launch_root()
  {
    const char *rank = launcher_rank();
    return rank == nullptr || std::string(rank) == "0";
  }

  void
  prepare_single_process_mpi()
  {
    if (launcher_rank() != nullptr || std::getenv("OMPI_COMM_WORLD_SIZE"))
      return;
    // overwrite = 0: a setting of the user's stays.
    setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
    setenv("OMPI_MCA_pml", "ob1", 0);
  }
} // namespace rollnip
