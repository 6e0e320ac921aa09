#include <rollnip/postprocess/body_values.h>
#include <rollnip/problem.h>
#include <rollnip/solvers/iteration_controls.h>

#include <iomanip>

namespace rollnip
{
  RollProblem::RollProblem(const Parameters::AllParameters &parameters,
                           const MPI_Comm                   mpi_communicator)
      : parameters(parameters)
      , mpi_communicator(mpi_communicator)
      , pcout(std::cout,
              Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      , run_clock(mpi_communicator, true)
      , timer(mpi_communicator,
              pcout,
              parameters.output.print_timing ? TimerOutput::summary
                                             : TimerOutput::never,
              TimerOutput::wall_times)
      , roll_body(parameters, mpi_communicator, timer)
      , linear_solver(parameters.linear_solver, pcout, timer)
      , newton(parameters.nonlinear_solver, roll_body, linear_solver, pcout)
      , stepper(parameters.load_stepping, roll_body, newton, pcout)
      , writer(parameters, mpi_communicator, timer)
  {}

  void
  RollProblem::setup()
  {
    roll_body.setup();
    linear_solver.reinit(roll_body, true);
  }

  void
  RollProblem::fit_mesh_to_nip(const double theta0)
  {
    roll_body.fit_mesh_to_nip(theta0);
    linear_solver.reinit(roll_body, false);
  }

  void
  RollProblem::log_step(const StepRecord &r)
  {
    pcout << std::setw(5) << r.step << std::fixed << std::setprecision(6)
          << std::setw(15) << r.load_fraction << std::setw(8)
          << r.newton_iterations << std::scientific << std::setprecision(3)
          << std::setw(16) << r.residual << std::fixed << std::setprecision(6)
          << std::setw(17) << r.u_r_centre << std::setw(11)
          << std::setprecision(4) << r.nip_load << std::setw(11)
          << std::setprecision(2) << r.wall_time << std::endl;
    const bool full =
      r.load_fraction >= 1. - IterationControls::full_load_slack;
    if (parameters.output.write_vtu &&
        (parameters.output.vtu_every_step || full))
      write_vtu(r.step, r.load_fraction);
    if (parameters.output.write_csv && parameters.output.csv_every_step)
      {
        // Collective; rank 0 writes.
        const SurfaceData data = surface_data(r.load_fraction);
        if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
          writer.write_surface_csv(data,
                                   "-" + Utilities::int_to_string(r.step, 4));
      }
  }

  RunStatus
  RollProblem::run(const bool from_current_state, const double first_increment)
  {
    if (log_steps)
      pcout << " step  load fraction  Newton  |R_u|/|F_ext|   u_r(R0,0) [mm]"
               "   P [N/mm]   time [s]"
            << std::endl;
    const RunStatus status = stepper.run(from_current_state,
                                         first_increment,
                                         [this](const StepRecord &r) {
                                           if (log_steps)
                                             log_step(r);
                                         });
    // A stopped run still leaves the last converged state for ParaView.
    if (!status.converged && status.steps > 0 && log_steps &&
        parameters.output.write_vtu && !parameters.output.vtu_every_step)
      write_vtu(status.steps, status.load_fraction);
    return status;
  }

  SurfaceData
  RollProblem::surface_data(const double load_fraction) const
  {
    return rollnip::surface_data(roll_body, load_fraction);
  }

  Tensor<1, dim>
  RollProblem::load_resultant(const double load_fraction) const
  {
    return rollnip::load_resultant(roll_body, load_fraction);
  }

  double
  RollProblem::radial_displacement_on_line_of_centres() const
  {
    return rollnip::radial_displacement_on_line_of_centres(roll_body);
  }

  double
  RollProblem::radial_displacement_at(const Point<dim> &X) const
  {
    return rollnip::radial_displacement_at(roll_body, X);
  }

  void
  RollProblem::write_results(const RunStatus &status)
  {
    const RunStatistics statistics{stepper.log(),
                                   newton.log(),
                                   stepper.n_cutbacks(),
                                   newton.n_chord_steps,
                                   roll_body.n_assemblies(),
                                   linear_solver.n_factorizations(),
                                   linear_solver.n_symbolic_analyses(),
                                   linear_solver.gmres_iterations(),
                                   linear_solver.gmres_solves(),
                                   run_clock.wall_time(),
                                   stepper.wall_time(),
                                   timer.get_summary_data(
                                     TimerOutput::total_wall_time)};
    writer.write_results(roll_body, statistics, status);
  }
} // namespace rollnip
