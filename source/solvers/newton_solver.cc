#include <rollnip/run_errors.h>
#include <rollnip/solvers/iteration_controls.h>
#include <rollnip/solvers/newton_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace rollnip
{
  NewtonSolver::NewtonSolver(const Parameters::NonlinearSolver &parameters,
                             RollBody                          &body,
                             LinearSolver                      &linear_solver,
                             ConditionalOStream                &pcout)
      : parameters(parameters)
      , body(body)
      , linear_solver(linear_solver)
      , pcout(pcout)
  {}

  double
  NewtonSolver::Errors::merit() const
  {
    return std::sqrt(e_R * e_R + e_J * e_J);
  }

  double
  NewtonSolver::residual_round_off_floor() const
  {
    // Stresses of order G summed over the cells: I + grad u loses the
    // digits of u next to 1, whatever the load. In a layered cover the
    // stiffest layer carries the largest stresses, and their round-off.
    const MaterialTable &materials = body.materials();
    double               G         = 0;
    for (unsigned int l = 0; l < materials.n_layers(); ++l)
      G = std::max(G, materials[l].shear_modulus());
    const double cell_size = std::sqrt(body.area() / body.n_cells());
    return IterationControls::round_off_factor *
           std::numeric_limits<double>::epsilon() * G * cell_size *
           std::sqrt(double(body.n_dofs()));
  }

  NewtonSolver::Errors
  NewtonSolver::measure() const
  {
    const auto    &R    = body.residual();
    const MPI_Comm comm = body.communicator();
    double         r_p2 = 0, sum_abs = 0;
    for (const auto i : body.pressure_dofs())
      {
        r_p2 += R[i] * R[i];
        sum_abs += std::abs(R[i]);
      }
    r_p2                 = Utilities::MPI::sum(r_p2, comm);
    const double r_total = R.l2_norm();
    const double r_u     = std::sqrt(std::max(0., r_total * r_total - r_p2));
    const double f_ext   = body.external_force().l2_norm();
    const double scale   = f_ext > 0 ? f_ext : 1.;
    Errors       e;
    e.e_R     = r_u / scale;
    e.floor_R = residual_round_off_floor() / scale;
    e.e_J     = Utilities::MPI::sum(sum_abs, comm) / body.area();
    return e;
  }

  double
  NewtonSolver::line_search(const TrilinosWrappers::MPI::Vector &update,
                            const double                         load_fraction,
                            Errors                              &errors,
                            double                              &min_J,
                            bool                                &decreased)
  {
    const bool                          check_J = !body.materials().is_linear();
    const double                        old_merit = errors.merit();
    const TrilinosWrappers::MPI::Vector base(body.owned_solution());
    TrilinosWrappers::MPI::Vector       trial(base);
    double                              alpha = 1;
    for (unsigned int ls = 0;; ++ls)
      {
        trial = base;
        trial.add(alpha, update);
        body.set_solution(trial);
        min_J  = body.assemble(load_fraction, false);
        errors = measure();
        decreased =
          (!check_J || min_J > 0) && std::isfinite(errors.e_R) &&
          errors.merit() <
            (1. - IterationControls::sufficient_decrease * alpha) * old_merit;
        if (decreased || !parameters.line_search ||
            ls >= parameters.max_line_search_steps)
          return alpha;
        alpha *= IterationControls::line_search_factor;
      }
  }

  bool
  NewtonSolver::solve(const double load_fraction, const unsigned int step)
  {
    const TrilinosWrappers::MPI::Vector start(body.owned_solution());
    TrilinosWrappers::MPI::Vector       update(start);
    last_chord_update = 0;
    // J <= 0 means an inverted cell in finite strain; in linear theory J
    // of I + grad u has no meaning and is not checked.
    const bool check_J = !body.materials().is_linear();
    double     min_J   = body.assemble(load_fraction, true);
    Errors     errors  = measure();
    auto       broken  = [&]() {
      return (check_J && !(min_J > 0)) || !std::isfinite(errors.e_R);
    };
    if (parameters.verbose)
      pcout << "      iter  |R_u|/|F|     sum|J-1|/A    |du|/|u|    step"
            << std::endl;

    // Iterations in a row whose line search found no decrease: a few mean
    // the iteration is stuck (beyond a limit load, say), and the step is
    // given up at once rather than after the full iteration budget.
    unsigned int stalled = 0;
    last_failure.clear();
    for (unsigned int it = 1; it <= parameters.max_iterations && !broken();
         ++it)
      {
        if (!solve_linear_system(update))
          break;

        bool         decreased = false;
        const double alpha =
          line_search(update, load_fraction, errors, min_J, decreased);
        const double u_norm = body.owned_solution().l2_norm();
        const double e_u =
          alpha * update.l2_norm() / (u_norm > 0 ? u_norm : 1.);
        records.push_back(
          {step, it, load_fraction, errors.e_R, errors.e_J, e_u, alpha});
        if (parameters.verbose)
          pcout << "      " << std::setw(4) << it << std::scientific
                << std::setprecision(3) << "  " << errors.e_R << "     "
                << errors.e_J << "     " << e_u << "   " << std::fixed
                << std::setprecision(3) << alpha << std::endl;
        if (broken())
          break;
        stalled = decreased ? 0 : stalled + 1;
        if (converged(errors, e_u) ||
            (converged(errors, 0.) && chord_step(load_fraction, errors, min_J)))
          {
            last_iterations = it;
            last_residual   = errors.e_R;
            return true;
          }
        if (parameters.line_search &&
            stalled >= IterationControls::stuck_iterations)
          {
            last_failure = "the line search found no decrease in " +
                           std::to_string(stalled) + " iterations in a row";
            break;
          }
        // The tangent at the accepted point, for the next iteration.
        min_J = body.assemble(load_fraction, true);
      }

    explain_failure(check_J && !(min_J > 0), errors);
    body.set_solution(start);
    body.rollback_state();
    return false;
  }

  bool
  NewtonSolver::solve_linear_system(TrilinosWrappers::MPI::Vector &update)
  {
    TrilinosWrappers::MPI::Vector rhs(body.residual());
    rhs *= -1.;
    update = 0;
    try
      {
        linear_solver.factorize(body);
        linear_solver.solve(body, rhs, update);
      }
    catch (const std::exception &e)
      {
        // Only the iterative solver fails softly (too many iterations):
        // the step is cut back like a failed Newton iteration.
        if (!linear_solver.is_iterative())
          throw;
        last_failure = one_line_message(e);
        pcout << "      (" << last_failure << ")" << std::endl;
        return false;
      }
    return true;
  }

  bool
  NewtonSolver::converged(const Errors &errors, const double e_u) const
  {
    return errors.e_R < parameters.residual_tolerance + errors.floor_R &&
           errors.e_J < parameters.constraint_tolerance &&
           (e_u < parameters.increment_tolerance ||
            errors.e_R < IterationControls::residual_only_convergence *
                           parameters.residual_tolerance);
  }

  bool
  NewtonSolver::chord_step(const double load_fraction,
                           Errors      &errors,
                           double      &min_J)
  {
    const TrilinosWrappers::MPI::Vector before(body.owned_solution());
    TrilinosWrappers::MPI::Vector       rhs(body.residual());
    rhs *= -1.;
    TrilinosWrappers::MPI::Vector update(rhs);
    update = 0;
    try
      {
        linear_solver.solve(body, rhs, update);
      }
    catch (const std::exception &)
      {
        // Only GMRES fails softly; a full Newton iteration follows.
        if (!linear_solver.is_iterative())
          throw;
        return false;
      }
    // e_u as Newton measures it, relative to the state it leads to.
    TrilinosWrappers::MPI::Vector trial(before);
    trial += update;
    const double u_norm = trial.l2_norm();
    const double e_u    = update.l2_norm() / (u_norm > 0 ? u_norm : 1.);
    if (!(e_u < parameters.increment_tolerance))
      {
        if (parameters.verbose)
          pcout << "            chord update " << std::scientific
                << std::setprecision(3) << e_u << " (not taken)" << std::endl;
        return false;
      }
    body.set_solution(trial);
    const double new_J      = body.assemble(load_fraction, false);
    const Errors new_errors = measure();
    const bool   check_J    = !body.materials().is_linear();
    const bool   done = (!check_J || new_J > 0) && converged(new_errors, e_u);
    if (parameters.verbose)
      pcout << "            chord " << std::scientific << std::setprecision(3)
            << new_errors.e_R << "     " << new_errors.e_J << "     " << e_u
            << (done ? "" : "   (not taken)") << std::endl;
    if (!done)
      {
        // Back to the Newton iterate: the next iteration starts from it
        // and assembles there (its residual and tangent) first.
        body.set_solution(before);
        return false;
      }
    errors = new_errors;
    min_J  = new_J;
    ++n_chord_steps;
    last_chord_update = e_u;
    return true;
  }

  void
  NewtonSolver::explain_failure(const bool inverted, const Errors &errors)
  {
    if (inverted)
      {
        last_failure = "J <= 0 somewhere: the cover would invert";
        pcout << "      (" << last_failure << ")" << std::endl;
      }
    else if (!std::isfinite(errors.e_R))
      last_failure = "the residual is not finite";
    else if (last_failure.empty())
      {
        std::ostringstream why;
        why << "no convergence in " << parameters.max_iterations
            << " iterations (|R_u|/|F| " << std::scientific
            << std::setprecision(2) << errors.e_R << ", sum|J-1|/A "
            << errors.e_J << ")";
        last_failure = why.str();
      }
  }
} // namespace rollnip
