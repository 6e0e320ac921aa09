#ifndef rollnip_problem_h
#define rollnip_problem_h

#include <deal.II/base/timer.h>

#include <rollnip/body/roll_body.h>
#include <rollnip/contact/contact_body.h>
#include <rollnip/global.h>
#include <rollnip/output/output_writer.h>
#include <rollnip/parameters.h>
#include <rollnip/postprocess/surface_data.h>
#include <rollnip/solvers/linear_solver.h>
#include <rollnip/solvers/load_stepper.h>
#include <rollnip/solvers/newton_solver.h>

#include <functional>
#include <string>

namespace rollnip
{
  /**
   * One run of one cover: the body (body/roll_body.h) with the algorithms
   * that drive it, the linear solver, Newton and the load stepper, and the
   * output writer, wired together. Drivers (main, the contact iteration,
   * the studies) hold one of these per run; everything it does is done by
   * its parts.
   */
  class RollProblem : public ContactBody
  {
  public:
    RollProblem(const Parameters::AllParameters &parameters,
                const MPI_Comm                   mpi_communicator);

    /// Mesh, DoFs, constraints, sparsity.
    void
    setup();

    RollBody &
    body()
    {
      return roll_body;
    }
    const RollBody &
    body() const
    {
      return roll_body;
    }

    bool
    has_nip_fitted_mesh() const override
    {
      return roll_body.has_nip_fitted_mesh();
    }
    /// Moves the nip-fitted mesh so that the contact edge is the surface
    /// vertex at @p theta0 [rad].
    void
    fit_mesh_to_nip(const double theta0) override;
    double
    max_nip_angle() const override
    {
      return roll_body.max_nip_angle();
    }
    MeshQuality
    cell_quality() const override
    {
      return roll_body.cell_quality();
    }

    /// Ramps the load from 0 (or the current state) to 1; writes output of
    /// converged steps when the step log is on; never throws for a load it
    /// cannot reach but reports it in the status. The first increment is
    /// @p first_increment if positive, else 1 / (Initial steps).
    RunStatus
    run(const bool   from_current_state = false,
        const double first_increment    = 0) override;

    /// Replaces the follower pressure by @p pressure(Theta, lambda) [MPa].
    void
    set_pressure(FollowerLoad::Pressure pressure) override
    {
      roll_body.load().set_pressure(std::move(pressure));
    }

    /// d R_u / d s for the extra follower pressure s g(Theta).
    TrilinosWrappers::MPI::Vector
    pressure_load_derivative(
      const std::function<double(double)> &g) const override
    {
      return roll_body.pressure_load_derivative(g);
    }

    /// Assembles the residual (and the tangent) of the current state;
    /// returns the smallest J.
    double
    assemble(const double load_fraction, const bool with_matrix) override
    {
      return roll_body.assemble(load_fraction, with_matrix);
    }
    /// Factorises the assembled tangent for repeated solves.
    void
    factorize_tangent() override
    {
      linear_solver.factorize(roll_body);
    }
    /// K x[k] = rhs[k] for each k with the last factorisation.
    void
    solve_with_tangent(const std::vector<TrilinosWrappers::MPI::Vector> &rhs,
                       std::vector<TrilinosWrappers::MPI::Vector> &x) override
    {
      linear_solver.solve(roll_body, rhs, x);
    }

    /// No timing table when the object goes away (after an error).
    void
    silence_timer()
    {
      timer.disable_output();
    }
    /// Where write_vtu() and write_results() put files.
    void
    set_output_directory(const std::string &directory)
    {
      writer.set_directory(directory);
    }
    /// write_vtu() turns the body half a turn about @p centre (none: as
    /// computed; OutputWriter::set_placement).
    void
    set_vtu_placement(const std::optional<Point<dim>> &centre)
    {
      writer.set_placement(centre);
    }
    /// Whether run() prints one line per load step and writes VTU (on by
    /// default; the contact iteration turns it off for its inner solves).
    void
    set_step_log(const bool on) override
    {
      log_steps = on;
    }

    MPI_Comm
    communicator() const override
    {
      return mpi_communicator;
    }

    SurfaceData
    surface_data(const double load_fraction) const;
    Tensor<1, dim>
    load_resultant(const double load_fraction) const override;
    double
    radial_displacement_on_line_of_centres() const;
    double
    radial_displacement_at(const Point<dim> &X) const;

    void
    write_vtu(const unsigned int step, const double load_fraction)
    {
      writer.write_vtu(roll_body, step, load_fraction);
    }
    /// The CSV files and summary.txt for the current state.
    void
    write_results(const RunStatus &status);

    const std::vector<NewtonRecord> &
    newton_log() const
    {
      return newton.log();
    }
    const std::vector<StepRecord> &
    step_log() const
    {
      return stepper.log();
    }
    unsigned int
    gmres_iterations() const
    {
      return linear_solver.gmres_iterations();
    }
    /// Newton solves that converged with a chord step.
    unsigned int
    chord_steps() const
    {
      return newton.n_chord_steps;
    }
    /// e_u of the chord step that ended the last Newton solve (0: none).
    double
    last_chord_update() const
    {
      return newton.last_chord_update;
    }
    const TrilinosWrappers::MPI::Vector &
    owned_solution() const override
    {
      return roll_body.owned_solution();
    }
    std::vector<SurfaceNode>
    surface_nodes() const override
    {
      return outer_surface_nodes(roll_body.dofs());
    }
    const TrilinosWrappers::MPI::Vector &
    current_solution() const override
    {
      return roll_body.solution();
    }
    void
    set_solution(const TrilinosWrappers::MPI::Vector &owned) override
    {
      roll_body.set_solution(owned);
    }
    const TrilinosWrappers::MPI::Vector &
    residual() const
    {
      return roll_body.residual();
    }
    const TrilinosWrappers::SparseMatrix &
    tangent() const
    {
      return roll_body.tangent();
    }
    const IndexSet &
    locally_owned() const override
    {
      return roll_body.locally_owned();
    }
    const AffineConstraints<double> &
    constraints_object() const
    {
      return roll_body.constraints();
    }
    types::global_dof_index
    n_dofs() const
    {
      return roll_body.n_dofs();
    }
    unsigned int
    n_cells() const
    {
      return roll_body.n_cells();
    }
    const DoFHandler<dim> &
    dofs() const
    {
      return roll_body.dofs();
    }

  private:
    /// The screen line of a converged step, its VTU and surface CSV.
    void
    log_step(const StepRecord &r);

    const Parameters::AllParameters &parameters;
    MPI_Comm                         mpi_communicator;
    ConditionalOStream               pcout;
    Timer                            run_clock;
    TimerOutput                      timer;
    RollBody                         roll_body;
    LinearSolver                     linear_solver;
    NewtonSolver                     newton;
    LoadStepper                      stepper;
    OutputWriter                     writer;
    bool                             log_steps = true;
  };
} // namespace rollnip

#endif
