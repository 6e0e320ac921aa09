#ifndef rollnip_mpi_start_h
#define rollnip_mpi_start_h

namespace rollnip
{
  /// Whether this process is rank 0 of its launcher (mpirun, mpiexec or
  /// srun), or was started without one; readable before MPI_Init, so that
  /// --help and bad arguments are answered without starting MPI.
  bool
  is_launch_root();

  /**
   * Prepares Open MPI for a process started without a launcher (a plain
   * `rollnip FILE.prm`): such a singleton would fork an orted server
   * (about 0.2 s) and load the PSM2, PSM and OFI network components
   * (about 0.2 s, libpsm2 calibrating its clock) although one process
   * communicates with nobody. Sets OMPI_MCA_ess_singleton_isolated and
   * OMPI_MCA_pml = ob1 unless the user set them; does nothing under a
   * launcher. Call before MPI_Init.
   */
  void
  prepare_single_process_mpi();
} // namespace rollnip

#endif
