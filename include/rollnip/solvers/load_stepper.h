#ifndef rollnip_solvers_load_stepper_h
#define rollnip_solvers_load_stepper_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <rollnip/body/roll_body.h>
#include <rollnip/parameters.h>
#include <rollnip/solvers/newton_solver.h>

#include <functional>
#include <string>
#include <vector>

namespace rollnip
{
  /// One converged load step.
  struct StepRecord
  {
    unsigned int step;
    double       load_fraction;
    unsigned int newton_iterations;
    double       residual;
    double       nip_load;   ///< P [N/mm]
    double       u_r_centre; ///< [mm]
    double       wall_time;  ///< [s] since the start of the solve
  };

  /// How a run ended.
  struct RunStatus
  {
    bool         converged     = false;
    double       load_fraction = 0; ///< the last converged load fraction
    unsigned int steps         = 0; ///< converged steps of this run
    std::string  message;           ///< why it stopped, if it did not converge
  };

  /**
   * Ramps the load fraction of a body from 0 (or its current state) to 1
   * with adaptive increments: a step that converges fast lets the next one
   * grow, a failed one is cut back; the start of each step is extrapolated
   * through the last two converged states. It never throws for a load it
   * cannot reach but says why in the status.
   */
  class LoadStepper
  {
  public:
    /// Called after every converged step (for the screen and the files).
    using StepObserver = std::function<void(const StepRecord &)>;

    LoadStepper(const Parameters::LoadStepping &parameters,
                RollBody                       &body,
                NewtonSolver                   &newton,
                ConditionalOStream             &pcout);

    /// The first increment is @p first_increment if positive, else
    /// 1 / (Initial steps); linear theory takes the whole load at once.
    RunStatus
    run(const bool          from_current_state,
        const double        first_increment,
        const StepObserver &on_step);

    const std::vector<StepRecord> &
    log() const
    {
      return records;
    }
    unsigned int
    n_cutbacks() const
    {
      return cutback_count;
    }
    /// [s] since the start of the last run.
    double
    wall_time() const
    {
      return wall_clock.wall_time();
    }

  private:
    /// Solves load step @p step at @p target from the state extrapolated
    /// through the converged states at @p previous_lambda (@p previous)
    /// and @p lambda (the current one); restores the current state if
    /// Newton fails from there.
    bool
    solve_from_prediction(const double                         lambda,
                          const double                         target,
                          const double                         previous_lambda,
                          const TrilinosWrappers::MPI::Vector &previous,
                          const unsigned int                   step);

    /// The step record of the state just converged at @p lambda.
    StepRecord
    record(const unsigned int step, const double lambda) const;

    /// Why the load stepping gives up after a failure at @p target, or ""
    /// to cut back and carry on.
    std::string
    give_up_reason(const double lambda, const double target);

    const Parameters::LoadStepping &parameters;
    RollBody                       &body;
    NewtonSolver                   &newton;
    ConditionalOStream             &pcout;
    Timer                           wall_clock;
    std::vector<StepRecord>         records;
    unsigned int                    cutback_count = 0;

    /// Per run: the increment, failures in a row, and the stall window.
    double       increment         = 0;
    unsigned int cutbacks_in_a_row = 0;
    unsigned int run_cutbacks      = 0;
    double       window_start      = 0;
  };
} // namespace rollnip

#endif
