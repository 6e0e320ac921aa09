#ifndef rollnip_solvers_sparse_direct_h
#define rollnip_solvers_sparse_direct_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <rollnip/global.h>

#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>

#include <memory>
#include <string>
#include <vector>

namespace rollnip
{
  /**
   * A sparse direct solver (Amesos: MUMPS or KLU) that keeps its symbolic
   * analysis while the sparsity pattern stays the same: Newton steps, load
   * steps and contact iterations only refactorise numerically. deal.II's
   * SolverDirect analyses the pattern again at every initialize().
   *
   * MUMPS sometimes underestimates its workspace on strongly graded meshes
   * (INFOG(1) = -9); the analysis is then redone with a larger relaxation
   * (ICNTL(14) = 100, then 400 %), and KLU takes over only if that fails.
   */
  class SparseDirectSolver
  {
  public:
    explicit SparseDirectSolver(const std::string &name);

    /// The next factorize() analyses the pattern again (after a new mesh).
    void
    forget_pattern();

    /// Numeric factorisation of @p matrix; symbolic too on a new pattern.
    void
    factorize(const TrilinosWrappers::SparseMatrix &matrix);

    /// x = A^-1 b with the last factorisation.
    void
    solve(const TrilinosWrappers::MPI::Vector &b,
          TrilinosWrappers::MPI::Vector       &x);

    /// x[k] = A^-1 b[k] for every k with the last factorisation; MUMPS
    /// takes all of them in one solve phase, which reads the factors once
    /// for all (blocked triangular solves) instead of once per vector.
    void
    solve(const std::vector<TrilinosWrappers::MPI::Vector> &b,
          std::vector<TrilinosWrappers::MPI::Vector>       &x);

    const std::string &
    name() const
    {
      return solver_name;
    }

    unsigned int n_analyses       = 0;
    unsigned int n_factorisations = 0;

  private:
    /// A fresh solver for the current operator, analysed; false on failure.
    bool
    analyse(const int workspace_relaxation);

    std::string                        solver_name;
    Epetra_LinearProblem               linear_problem;
    std::unique_ptr<Amesos_BaseSolver> solver;
    const Epetra_CrsMatrix            *analysed_matrix = nullptr;
    int                                relaxation      = 0;
  };
} // namespace rollnip

#endif
