#ifndef rollnip_solvers_newton_solver_h
#define rollnip_solvers_newton_solver_h

#include <deal.II/base/conditional_ostream.h>

#include <deal.II/lac/trilinos_vector.h>

#include <rollnip/body/roll_body.h>
#include <rollnip/parameters.h>
#include <rollnip/solvers/linear_solver.h>

#include <string>
#include <vector>

namespace rollnip
{
  /// One Newton iteration, as logged (doc/intro.md, section 5).
  struct NewtonRecord
  {
    unsigned int step;
    unsigned int iteration;
    double       load_fraction;
    double       residual;   ///< |R_u| / |F_ext|
    double       constraint; ///< sum |integral (J - 1)| / |Omega|
    double       increment;  ///< |du| / |u|
    double       step_length;
  };

  /**
   * Full Newton with a backtracking line search at a fixed load fraction
   * (doc/intro.md, section 5). The tests of convergence use
   *   e_R = |R_u| / |F_ext|,  e_J = sum_K |int_K (J - 1)| / |Omega|,
   *   e_u = |du| / |u|  (Euclidean norms of nodal vectors);
   * a step converges when e_R and e_J are below their tolerances and
   * either e_u is below its tolerance or e_R is far below its own. A
   * step that meets all but e_u is followed by a chord step (the last
   * tangent's factorisation or preconditioner applied to the new
   * residual, and a residual assembly), whose update and end state are
   * tested in the same way (and J > 0); it replaces the Newton iteration
   * that would mostly confirm convergence. Its own update estimates the
   * state's error before it (Deuflhard, Newton Methods for Nonlinear
   * Problems, 2004, section 2.1); the error left after it is about that
   * update times the last Newton update, where a Newton iteration would
   * leave its square. It is not an iteration in log(). The
   * line search halves the step while the merit sqrt(e_R^2 + e_J^2) does
   * not decrease or some J <= 0.
   */
  class NewtonSolver
  {
  public:
    NewtonSolver(const Parameters::NonlinearSolver &parameters,
                 RollBody                          &body,
                 LinearSolver                      &linear_solver,
                 ConditionalOStream                &pcout);

    /// Solves at @p load_fraction from the body's state; false on failure,
    /// with the state left as it was.
    bool
    solve(const double load_fraction, const unsigned int step);

    /// Iterations and e_R of the last converged solve.
    unsigned int last_iterations = 0;
    double       last_residual   = 0;
    /// Solves that converged with a chord step instead of an iteration,
    /// and e_u of the chord step that ended the last solve (0: none).
    unsigned int n_chord_steps     = 0;
    double       last_chord_update = 0;

    /// Why the last failed solve failed, in words for the user.
    std::string last_failure;

    const std::vector<NewtonRecord> &
    log() const
    {
      return records;
    }

  private:
    /// The convergence measures of the assembled residual, and the
    /// round-off floor of e_R at this load.
    struct Errors
    {
      double e_R = 0, e_J = 0, floor_R = 0;
      double
      merit() const;
    };

    Errors
    measure() const;

    /// |R_u| cannot fall below round-off relative to stresses of order G:
    /// for a tiny load that floor can exceed Residual tolerance, so the
    /// test adds it and any load scale stays reachable [N/mm].
    double
    residual_round_off_floor() const;

    /// Solves the tangent system for the Newton @p update; false (with
    /// last_failure) when the iterative solver does not converge.
    bool
    solve_linear_system(TrilinosWrappers::MPI::Vector &update);

    /// The convergence test of the class documentation.
    bool
    converged(const Errors &errors, const double e_u) const;

    /// The chord step of the class documentation at @p load_fraction:
    /// true if it converged (the state moved, @p errors and @p min_J of
    /// the new state); false with the state, @p errors and @p min_J as
    /// they were.
    bool
    chord_step(const double load_fraction, Errors &errors, double &min_J);

    /// Sets last_failure for a failed solve that ended with @p errors
    /// (@p inverted: some J <= 0), unless a cause is already set.
    void
    explain_failure(const bool inverted, const Errors &errors);

    /// Backtracks along @p update from the current state; returns the
    /// step length taken, with @p errors, @p min_J and @p decreased of the
    /// accepted point.
    double
    line_search(const TrilinosWrappers::MPI::Vector &update,
                const double                         load_fraction,
                Errors                              &errors,
                double                              &min_J,
                bool                                &decreased);

    const Parameters::NonlinearSolver &parameters;
    RollBody                          &body;
    LinearSolver                      &linear_solver;
    ConditionalOStream                &pcout;
    std::vector<NewtonRecord>          records;
  };
} // namespace rollnip

#endif
