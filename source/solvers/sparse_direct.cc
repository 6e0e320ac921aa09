#include <deal.II/base/exceptions.h>

#include <rollnip/output/silence_cerr.h>
#include <rollnip/solvers/sparse_direct.h>

#include <Amesos.h>
#include <Amesos_config.h>
#ifdef HAVE_AMESOS_MUMPS
#include <Amesos_Mumps.h>
#endif

namespace rollnip
{
  SparseDirectSolver::SparseDirectSolver(const std::string &name)
      : solver_name(name)
  {}

  void
  SparseDirectSolver::forget_pattern()
  {
    solver.reset();
    analysed_matrix = nullptr;
  }

  bool
  SparseDirectSolver::analyse(const int workspace_relaxation)
  {
    Amesos factory;
    solver.reset(factory.Create(solver_name.c_str(), linear_problem));
    AssertThrow(solver != nullptr,
                ExcMessage("Linear solver/Direct solver: '" + solver_name +
                           "' is not available in this Trilinos"));
#ifdef HAVE_AMESOS_MUMPS
    if (auto *mumps = dynamic_cast<Amesos_Mumps *>(solver.get()))
      if (workspace_relaxation > 0)
        mumps->SetICNTL(14, workspace_relaxation);
#endif
    ++n_analyses;
    return solver->SymbolicFactorization() == 0;
  }

  void
  SparseDirectSolver::factorize(const TrilinosWrappers::SparseMatrix &matrix)
  {
    const Epetra_CrsMatrix *A = &matrix.trilinos_matrix();
    ++n_factorisations;
    // Amesos_Mumps reports INFOG(1) = -9 (workspace too small) on std::cerr
    // before the retry below succeeds; a failure for good is thrown.
    const SilenceCerr silence;
    // A numeric failure with the current analysis is retried only with
    // more workspace than that analysis had.
    const bool numeric_failure = A == analysed_matrix && solver;
    if (numeric_failure && solver->NumericFactorization() == 0)
      return;

    // A new pattern, or a numeric failure with the old analysis: analyse
    // (again), with more MUMPS workspace on each retry, then KLU.
    linear_problem.SetOperator(const_cast<Epetra_CrsMatrix *>(A));
    analysed_matrix  = A;
    const bool mumps = solver_name == "Amesos_Mumps";
    for (const int r : {0, 100, 400})
      {
        if (r < relaxation || (numeric_failure && r == relaxation))
          continue;
        if (analyse(mumps ? r : 0) && solver->NumericFactorization() == 0)
          {
            relaxation = r;
            return;
          }
        if (!mumps)
          break;
      }
    AssertThrow(solver_name != "Amesos_Klu",
                ExcMessage("the sparse direct solver failed to factorise "
                           "the Newton matrix"));
    solver_name = "Amesos_Klu";
    AssertThrow(analyse(0) && solver->NumericFactorization() == 0,
                ExcMessage("the sparse direct solvers (MUMPS, then KLU) "
                           "failed to factorise the Newton matrix"));
  }

  void
  SparseDirectSolver::solve(const TrilinosWrappers::MPI::Vector &b,
                            TrilinosWrappers::MPI::Vector       &x)
  {
    Assert(solver, ExcMessage("factorize() first"));
    linear_problem.SetLHS(&x.trilinos_vector());
    linear_problem.SetRHS(const_cast<Epetra_MultiVector *>(
      static_cast<const Epetra_MultiVector *>(&b.trilinos_vector())));
    AssertThrow(solver->Solve() == 0,
                ExcMessage("the sparse direct solve failed"));
  }
} // namespace rollnip
