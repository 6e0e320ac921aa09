#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <rollnip/interrupt.h>
#include <rollnip/problem.h>
#include <rollnip/run_errors.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace rollnip
{
  namespace
  {
    /// The round-off floor of the residual, in units of epsilon x G x cell
    /// size x sqrt(DoFs); measured floors are about a tenth of it.
    constexpr double round_off_factor = 100;

    /// Cut-backs between two looks at the load fraction's progress.
    constexpr unsigned int stall_window = 20;
    /// The least progress per window, as a fraction of the load still to
    /// go, for the load stepping to carry on.
    constexpr double stall_progress = 1e-2;

    /// Notices a load fraction that stops growing over many cut-backs
    /// (each success is followed by a failure once the increment grows
    /// again), which would otherwise step for ever.
    struct StallGuard
    {
      unsigned int n_cutbacks   = 0;
      double       window_start = 0;

      bool
      stalled(const double lambda)
      {
        if (++n_cutbacks % stall_window != 0)
          return false;
        const bool stalled =
          lambda - window_start < stall_progress * (1 - window_start);
        window_start = lambda;
        return stalled;
      }
    };
  } // namespace

  double
  RollProblem::pressure_part_norm(const TrilinosWrappers::MPI::Vector &v) const
  {
    double sum = 0;
    for (const auto i : pressure_dofs)
      sum += v[i] * v[i];
    return std::sqrt(Utilities::MPI::sum(sum, mpi_communicator));
  }

  /**
   * One factorisation and solve of the Newton system K du = -R with a sparse
   * direct solver; the saddle-point matrix is indefinite and, with follower
   * loads, not symmetric.
   */
  void
  RollProblem::solve_linear_system(TrilinosWrappers::MPI::Vector &newton_update)
  {
    TrilinosWrappers::MPI::Vector rhs(system_rhs);
    rhs *= -1.;
    factorize_tangent();
    solve_with_tangent(rhs, newton_update);
  }

  void
  RollProblem::factorize_tangent()
  {
    TimerOutput::Scope t(timer, "linear solve");
    ++n_linear_solves;
    if (use_iterative_solver())
      {
        iterative_solver.initialize(
          system_matrix,
          preconditioner_matrix,
          constant_modes,
          parameters.discretization.displacement_degree() > 1);
        return;
      }
    const std::string before = direct_solver.name();
    direct_solver.factorize(system_matrix);
    if (direct_solver.name() != before)
      pcout << "      (" << before << " failed to factorise; switching to "
            << direct_solver.name() << ")" << std::endl;
  }

  void
  RollProblem::solve_with_tangent(const TrilinosWrappers::MPI::Vector &rhs,
                                  TrilinosWrappers::MPI::Vector       &x)
  {
    TimerOutput::Scope t(timer, "linear solve");
    if (use_iterative_solver())
      iterative_solver.solve(rhs, x);
    else
      direct_solver.solve(rhs, x);
    constraints.distribute(x);
  }

  double
  RollProblem::residual_round_off_floor() const
  {
    // Stresses of order G summed over the cells: I + grad u loses the
    // digits of u next to 1, whatever the load.
    const double G = 2 * (parameters.material.C1 + parameters.material.C2);
    const double cell_size =
      std::sqrt(domain_area / triangulation.n_global_active_cells());
    return round_off_factor * std::numeric_limits<double>::epsilon() * G *
           cell_size * std::sqrt(double(dof_handler.n_dofs()));
  }

  bool
  RollProblem::solve_from_prediction(
    const double                         lambda,
    const double                         target,
    const double                         previous_lambda,
    const TrilinosWrappers::MPI::Vector &previous,
    const unsigned int                   step)
  {
    // u(target) ~ u + (target - lambda) du/dlambda, the secant through the
    // last two converged states.
    const TrilinosWrappers::MPI::Vector converged(solution);
    const double s = (target - lambda) / (lambda - previous_lambda);
    solution.sadd(1. + s, -s, previous);
    locally_relevant_solution = solution;
    if (solve_load_step(target, step))
      return true;
    solution                  = converged;
    locally_relevant_solution = solution;
    return false;
  }

  void
  RollProblem::log_step(const unsigned int step,
                        const double       lambda,
                        const StepRecord  &r)
  {
    pcout << std::setw(5) << step << std::fixed << std::setprecision(6)
          << std::setw(15) << lambda << std::setw(8) << r.newton_iterations
          << std::scientific << std::setprecision(3) << std::setw(16)
          << r.residual << std::fixed << std::setprecision(6) << std::setw(17)
          << r.u_r_centre << std::setw(11) << std::setprecision(4) << r.nip_load
          << std::setw(11) << std::setprecision(2) << r.wall_time << std::endl;
    if (parameters.output.write_vtu &&
        (parameters.output.vtu_every_step || lambda >= 1. - 1e-12))
      write_vtu(step, lambda);
    if (parameters.output.write_csv && parameters.output.csv_every_step)
      {
        // Collective; rank 0 writes.
        const SurfaceData data = surface_data(lambda);
        if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
          write_surface_csv(data, "-" + Utilities::int_to_string(step, 4));
      }
  }

  /**
   * Full Newton at a fixed load fraction (doc/intro.md, section 5). The
   * tests of convergence use
   *   e_R = |R_u| / |F_ext|,  e_J = sum_K |int_K (J - 1)| / |Omega|,
   *   e_u = |du| / |u|  (Euclidean norms of nodal vectors);
   * a step converges when e_R and e_J are below their tolerances and
   * either e_u is below its tolerance or e_R is 1000 times below its own.
   * A backtracking line search halves the step while the residual grows or
   * some J <= 0. Returns false on failure, with the state left as it was.
   */
  bool
  RollProblem::solve_load_step(const double       load_fraction,
                               const unsigned int step)
  {
    const auto                   &nl = parameters.nonlinear_solver;
    TrilinosWrappers::MPI::Vector start(solution);
    TrilinosWrappers::MPI::Vector newton_update(solution);

    // e_R and the round-off floor relative to the load of this fraction
    // (assemble() sets the external force).
    const double floor_abs = residual_round_off_floor();
    double       floor_R   = 0;
    auto         measure   = [&](double &e_R, double &e_J) {
      const double r_p     = pressure_part_norm(system_rhs);
      const double r_total = system_rhs.l2_norm();
      const double r_u = std::sqrt(std::max(0., r_total * r_total - r_p * r_p));
      const double f_ext = external_force.l2_norm();
      e_R                = r_u / (f_ext > 0 ? f_ext : 1.);
      floor_R            = floor_abs / (f_ext > 0 ? f_ext : 1.);
      double s           = 0;
      for (const auto i : pressure_dofs)
        s += std::abs(system_rhs[i]);
      e_J = Utilities::MPI::sum(s, mpi_communicator) / domain_area;
    };
    auto merit = [](const double e_R, const double e_J) {
      return std::sqrt(e_R * e_R + e_J * e_J);
    };

    // J <= 0 means an inverted cell in finite strain; in linear theory J
    // of I + grad u has no meaning and is not checked.
    const bool check_J = !material.is_linear();
    double     min_J   = assemble(load_fraction, true);
    double     e_R, e_J;
    measure(e_R, e_J);
    if (nl.verbose)
      pcout << "      iter  |R_u|/|F|     sum|J-1|/A    |du|/|u|    step"
            << std::endl;

    // Iterations in a row whose line search found no decrease: two mean
    // the iteration is stuck (beyond a limit load, say), and the step is
    // given up at once rather than after the full iteration budget.
    unsigned int stalled = 0;
    for (unsigned int it = 1; it <= nl.max_iterations; ++it)
      {
        if ((check_J && !(min_J > 0)) || !std::isfinite(e_R))
          break;
        newton_update = 0;
        try
          {
            solve_linear_system(newton_update);
          }
        catch (const std::exception &e)
          {
            // Only the iterative solver fails softly (too many iterations):
            // the step is cut back like a failed Newton iteration.
            if (!use_iterative_solver())
              throw;
            pcout << "      (" << one_line_message(e) << ")" << std::endl;
            break;
          }

        // Backtracking on the merit sqrt(e_R^2 + e_J^2).
        const double                  old_merit = merit(e_R, e_J);
        TrilinosWrappers::MPI::Vector base(solution);
        double                        alpha     = 1;
        bool                          decreased = false;
        for (unsigned int ls = 0;; ++ls)
          {
            solution = base;
            solution.add(alpha, newton_update);
            locally_relevant_solution = solution;
            min_J                     = assemble(load_fraction, false);
            measure(e_R, e_J);
            const bool ok = (!check_J || min_J > 0) && std::isfinite(e_R) &&
                            merit(e_R, e_J) < (1. - 1e-4 * alpha) * old_merit;
            decreased = ok;
            if (ok || !nl.line_search || ls >= nl.max_line_search_steps)
              break;
            alpha *= 0.5;
          }
        const double u_norm = solution.l2_norm();
        const double e_u =
          alpha * newton_update.l2_norm() / (u_norm > 0 ? u_norm : 1.);
        newton_records.push_back(
          {step, it, load_fraction, e_R, e_J, e_u, alpha});
        if (nl.verbose)
          pcout << "      " << std::setw(4) << it << std::scientific
                << std::setprecision(3) << "  " << e_R << "     " << e_J
                << "     " << e_u << "   " << std::fixed << std::setprecision(3)
                << alpha << std::endl;

        if ((check_J && !(min_J > 0)) || !std::isfinite(e_R))
          break;
        stalled = decreased ? 0 : stalled + 1;
        const bool converged =
          e_R < nl.residual_tolerance + floor_R &&
          e_J < nl.constraint_tolerance &&
          (e_u < nl.increment_tolerance || e_R < 1e-3 * nl.residual_tolerance);
        if (converged)
          {
            step_records.push_back({step,
                                    load_fraction,
                                    it,
                                    e_R,
                                    0.,
                                    radial_displacement_on_line_of_centres(),
                                    wall_clock.wall_time()});
            return true;
          }
        if (nl.line_search && stalled >= 2)
          break;
        // The tangent at the accepted point, for the next iteration.
        min_J = assemble(load_fraction, true);
      }

    solution                  = start;
    locally_relevant_solution = solution;
    if (check_J && !(min_J > 0))
      pcout << "      (J <= 0 somewhere: the cover would invert)" << std::endl;
    return false;
  }

  RunStatus
  RollProblem::run(const bool from_current_state, const double first_increment)
  {
    wall_clock.restart();
    const auto &ls = parameters.load_stepping;
    RunStatus   status;
    double      lambda = 0;
    // Linear theory: the whole load in one step (doc/intro.md, section 2).
    double       increment = material.is_linear()  ? 1.
                             : first_increment > 0 ? first_increment
                                                   : 1. / ls.n_initial_steps;
    unsigned int step = 0, cutbacks_in_a_row = 0;
    StallGuard   stall;
    // The converged state before the current one, for the predictor.
    TrilinosWrappers::MPI::Vector previous(solution);
    double                        previous_lambda = -1;

    if (!from_current_state)
      {
        solution                  = 0;
        locally_relevant_solution = solution;
        previous                  = 0;
        previous_lambda           = 0; // u = 0 at zero load
      }
    if (log_steps)
      pcout << " step  load fraction  Newton  |R_u|/|F_ext|   u_r(R0,0) [mm]"
               "   P [N/mm]   time [s]"
            << std::endl;
    while (lambda < 1. - 1e-12)
      {
        if (interrupt_requested(mpi_communicator))
          {
            status.message = interrupt_message();
            break;
          }
        const double target = std::min(1., lambda + increment);
        const TrilinosWrappers::MPI::Vector converged(solution);
        bool solved = ls.extrapolate && previous_lambda >= 0 &&
                      lambda > previous_lambda &&
                      solve_from_prediction(
                        lambda, target, previous_lambda, previous, step + 1);
        if (!solved)
          solved = solve_load_step(target, step + 1);
        if (solved)
          {
            previous        = converged;
            previous_lambda = lambda;
            ++step;
            lambda                         = target;
            cutbacks_in_a_row              = 0;
            StepRecord          &r         = step_records.back();
            const Tensor<1, dim> resultant = load_resultant(lambda);
            r.nip_load                     = -2. * resultant[0];
            if (log_steps)
              log_step(step, lambda, r);
            if (r.newton_iterations <= ls.fast_newton_iterations)
              increment *= ls.growth_factor;
          }
        else
          {
            ++n_cutbacks;
            ++cutbacks_in_a_row;
            increment *= 0.5;
            std::ostringstream msg;
            if (stall.stalled(lambda))
              {
                msg << "the load cannot be reached: the load fraction stalls "
                       "at "
                    << lambda << " (less than " << 100 * stall_progress
                    << " % of the remaining load gained over the last "
                    << stall_window << " cut-backs)";
                status.message = msg.str();
                break;
              }
            if (cutbacks_in_a_row > ls.max_cutbacks ||
                increment < ls.min_increment)
              {
                msg << "the load cannot be reached: Newton failed at load "
                       "fraction "
                    << target << " after " << cutbacks_in_a_row
                    << " failed attempt(s) in a row (increment now "
                    << increment << "); the last converged load fraction is "
                    << lambda;
                status.message = msg.str();
                break;
              }
            pcout << "      cutback: Newton failed at load fraction "
                  << std::setprecision(6) << target
                  << ", retrying with increment " << increment << std::endl;
          }
      }
    // A stopped run still leaves the last converged state for ParaView.
    if (lambda < 1. - 1e-12 && step > 0 && log_steps &&
        parameters.output.write_vtu && !parameters.output.vtu_every_step)
      write_vtu(step, lambda);
    status.converged     = lambda >= 1. - 1e-12;
    status.load_fraction = lambda;
    return status;
  }
} // namespace rollnip
