#ifndef rollnip_solvers_linear_solver_h
#define rollnip_solvers_linear_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/trilinos_vector.h>

#include <rollnip/body/roll_body.h>
#include <rollnip/parameters.h>
#include <rollnip/solvers/block_amg.h>
#include <rollnip/solvers/sparse_direct.h>

namespace rollnip
{
  /**
   * The linear solver of Linear solver/Method: a sparse direct solver, or
   * GMRES with the block AMG preconditioner. Factorises (or sets up) the
   * tangent of a body once, then solves with it any number of times; the
   * saddle-point matrix is indefinite and, with follower loads, not
   * symmetric.
   */
  class LinearSolver
  {
  public:
    LinearSolver(const Parameters::LinearSolver &parameters,
                 ConditionalOStream             &pcout,
                 TimerOutput                    &timer);

    bool
    is_iterative() const
    {
      return iterative;
    }

    /// After a new mesh of @p body (@p new_pattern) or moved vertices: the
    /// direct solver analyses a new pattern anew (moved vertices keep its
    /// analysis), the AMG takes the new Schur blocks.
    void
    reinit(const RollBody &body, const bool new_pattern);

    /// Factorises the tangent of @p body (after assemble(..., true)).
    void
    factorize(const RollBody &body);

    /// K x = rhs with the last factorisation; x is distributed through the
    /// constraints of @p body.
    void
    solve(const RollBody                      &body,
          const TrilinosWrappers::MPI::Vector &rhs,
          TrilinosWrappers::MPI::Vector       &x);

    /// The same for each of @p rhs, into @p x (sized alike): the direct
    /// solver takes them all in one pass.
    void
    solve(const RollBody                                   &body,
          const std::vector<TrilinosWrappers::MPI::Vector> &rhs,
          std::vector<TrilinosWrappers::MPI::Vector>       &x);

    unsigned int
    n_factorizations() const
    {
      return factorization_count;
    }
    unsigned int
    n_symbolic_analyses() const
    {
      return direct_solver.n_analyses;
    }
    unsigned int
    gmres_iterations() const
    {
      return iterative_solver.n_iterations;
    }
    unsigned int
    gmres_solves() const
    {
      return iterative_solver.n_solves;
    }

  private:
    const bool          iterative;
    ConditionalOStream &pcout;
    TimerOutput        &timer;
    SparseDirectSolver  direct_solver;
    BlockAMGSolver      iterative_solver;
    unsigned int        factorization_count = 0;
  };
} // namespace rollnip

#endif
