#include <rollnip/interrupt.h>
#include <rollnip/postprocess/body_values.h>
#include <rollnip/solvers/iteration_controls.h>
#include <rollnip/solvers/load_stepper.h>

#include <iomanip>
#include <sstream>

namespace rollnip
{
  LoadStepper::LoadStepper(const Parameters::LoadStepping &parameters,
                           RollBody                       &body,
                           NewtonSolver                   &newton,
                           ConditionalOStream             &pcout)
      : parameters(parameters)
      , body(body)
      , newton(newton)
      , pcout(pcout)
  {}

  bool
  LoadStepper::solve_from_prediction(
    const double                         lambda,
    const double                         target,
    const double                         previous_lambda,
    const TrilinosWrappers::MPI::Vector &previous,
    const unsigned int                   step)
  {
    // u(target) ~ u + (target - lambda) du/dlambda, the secant through the
    // last two converged states.
    const TrilinosWrappers::MPI::Vector converged(body.owned_solution());
    TrilinosWrappers::MPI::Vector       predicted(converged);
    const double s = (target - lambda) / (lambda - previous_lambda);
    predicted.sadd(1. + s, -s, previous);
    body.set_solution(predicted);
    if (newton.solve(target, step))
      return true;
    body.set_solution(converged);
    body.rollback_state();
    return false;
  }

  StepRecord
  LoadStepper::record(const unsigned int step, const double lambda) const
  {
    return {step,
            lambda,
            newton.last_iterations,
            newton.last_residual,
            -2. * load_resultant(body, lambda)[0],
            radial_displacement_on_line_of_centres(body),
            wall_clock.wall_time()};
  }

  std::string
  LoadStepper::give_up_reason(const double lambda, const double target)
  {
    using namespace IterationControls;
    ++cutback_count;
    ++cutbacks_in_a_row;
    increment *= cutback_factor;
    std::ostringstream msg;
    // A load fraction that stops growing over many cut-backs (each success
    // followed by a failure once the increment grows again) would
    // otherwise step for ever.
    if (++run_cutbacks % stall_window == 0)
      {
        const bool stalled =
          lambda - window_start < stall_progress * (1 - window_start);
        window_start = lambda;
        if (stalled)
          {
            msg << "the load cannot be reached: the load fraction stalls at "
                << lambda << " (less than " << 100 * stall_progress
                << " % of the remaining load gained over the last "
                << stall_window << " cut-backs)";
            return msg.str();
          }
      }
    if (cutbacks_in_a_row > parameters.max_cutbacks ||
        increment < parameters.min_increment)
      {
        msg << "the load cannot be reached: Newton failed at load fraction "
            << target << " after " << cutbacks_in_a_row
            << " failed attempt(s) in a row (increment now " << increment
            << "); the last converged load fraction is " << lambda
            << "; the last attempt: " << newton.last_failure;
        return msg.str();
      }
    pcout << "      cutback: Newton failed at load fraction "
          << std::setprecision(6) << target << ", retrying with increment "
          << increment << std::endl;
    return "";
  }

  RunStatus
  LoadStepper::run(const bool          from_current_state,
                   const double        first_increment,
                   const StepObserver &on_step)
  {
    const double full = 1. - IterationControls::full_load_slack;
    wall_clock.restart();
    increment         = body.materials().is_linear() ? 1.
                        : first_increment > 0        ? first_increment
                                              : 1. / parameters.n_initial_steps;
    cutbacks_in_a_row = run_cutbacks = 0;
    window_start                     = 0;
    RunStatus status;
    double    lambda = 0;
    // The converged state before the current one, for the predictor.
    TrilinosWrappers::MPI::Vector previous(body.owned_solution());
    double                        previous_lambda = -1;
    if (!from_current_state)
      {
        previous = 0;
        body.set_solution(previous);
        previous_lambda = 0; // u = 0 at zero load
      }
    while (lambda < full)
      {
        if (interrupt_requested(body.communicator()))
          {
            status.message = interrupt_message();
            break;
          }
        const double target = std::min(1., lambda + increment);
        const TrilinosWrappers::MPI::Vector converged(body.owned_solution());
        const unsigned int                  step = status.steps + 1;
        bool solved = parameters.extrapolate && previous_lambda >= 0 &&
                      lambda > previous_lambda &&
                      solve_from_prediction(
                        lambda, target, previous_lambda, previous, step);
        if (!solved)
          solved = newton.solve(target, step);
        if (!solved)
          {
            status.message = give_up_reason(lambda, target);
            if (!status.message.empty())
              break;
            continue;
          }
        body.commit_state();
        previous          = converged;
        previous_lambda   = lambda;
        lambda            = target;
        status.steps      = step;
        cutbacks_in_a_row = 0;
        records.push_back(record(step, lambda));
        if (on_step)
          on_step(records.back());
        if (records.back().newton_iterations <=
            parameters.fast_newton_iterations)
          increment *= parameters.growth_factor;
      }
    status.converged     = lambda >= full;
    status.load_fraction = lambda;
    return status;
  }
} // namespace rollnip
