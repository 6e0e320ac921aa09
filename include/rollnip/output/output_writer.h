#ifndef rollnip_output_output_writer_h
#define rollnip_output_output_writer_h

#include <deal.II/base/timer.h>

#include <rollnip/body/roll_body.h>
#include <rollnip/parameters.h>
#include <rollnip/postprocess/surface_data.h>
#include <rollnip/solvers/load_stepper.h>
#include <rollnip/solvers/newton_solver.h>

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rollnip
{
  /// The counters and logs of a run that go into its files.
  struct RunStatistics
  {
    const std::vector<StepRecord>   &steps;
    const std::vector<NewtonRecord> &newton;
    unsigned int                     cutbacks;
    unsigned int chord_steps; ///< Newton's (newton_solver.h)
    unsigned int assemblies;
    unsigned int linear_solves;
    unsigned int symbolic_factorisations;
    unsigned int gmres_iterations;
    unsigned int gmres_solves;
    double       run_wall_time;        ///< [s] since the problem was built
    double       last_solve_wall_time; ///< [s] of the last load-stepping solve
    std::map<std::string, double> times; ///< [s] per timer section
  };

  /**
   * The files of a run: VTU (one per rank), PVTU per step and one PVD for
   * the history; the surface and log CSV files; summary.txt. All are
   * written whole or not at all (atomic_file.h); rank 0 writes all but the
   * per-rank VTU pieces.
   */
  class OutputWriter
  {
  public:
    OutputWriter(const Parameters::AllParameters &parameters,
                 const MPI_Comm                   mpi_communicator,
                 TimerOutput                     &timer);

    /// A new directory starts a new PVD record.
    void
    set_directory(const std::string &directory);

    /// Turns the VTU half a turn about @p centre (none: as computed): the
    /// mating roll, whose own frame has the nip on +x, in the first roll's.
    void
    set_placement(const std::optional<Point<dim>> &centre);

    /// VTU of the state of @p body: displacement, q (cellwise for Q1-P0)
    /// and a nodal average of it, the derived stresses and strains, the
    /// layer (material id) and the rank of each cell (collective).
    void
    write_vtu(const RollBody    &body,
              const unsigned int step,
              const double       load_fraction);

    /// outer_surface<suffix>.csv and bond_surface<suffix>.csv (rank 0).
    void
    write_surface_csv(const SurfaceData &data, const std::string &suffix) const;

    /// The CSV files and summary.txt of the state of @p body (collective).
    void
    write_results(const RollBody      &body,
                  const RunStatistics &statistics,
                  const RunStatus     &status) const;

  private:
    void
    write_logs(const RunStatistics &statistics) const;
    /// summary.txt (output_summary.cc).
    void
    write_summary(const RollBody       &body,
                  const RunStatistics  &statistics,
                  const RunStatus      &status,
                  const SurfaceData    &data,
                  const Tensor<1, dim> &resultant,
                  const double          u_r) const;
    /// The line of the applied pressure for pressure scenes, else "".
    std::string
    applied_pressure_line() const;

    const Parameters::AllParameters            &parameters;
    MPI_Comm                                    mpi_communicator;
    TimerOutput                                &timer;
    std::string                                 directory;
    std::vector<std::pair<double, std::string>> pvd_records;
    std::optional<Point<dim>>                   placement;
  };
} // namespace rollnip

#endif
