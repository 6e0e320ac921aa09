#include <deal.II/base/exceptions.h>

#include <rollnip/output/silence_cerr.h>
#include <rollnip/solvers/sparse_direct.h>

#include <Amesos.h>
#include <Amesos_config.h>
#include <Epetra_MultiVector.h>
#ifdef HAVE_AMESOS_MUMPS
#include <Amesos_Mumps.h>
#endif

#include <algorithm>
#include <memory>

namespace rollnip
{
#ifdef HAVE_AMESOS_MUMPS
  namespace
  {
    /**
     * Amesos_Mumps with one MUMPS solve phase for several right-hand
     * sides: Amesos_Mumps::Solve() calls MUMPS once per column of its
     * multivector, and each call reads the whole factors for one vector.
     */
    class MultiRhsMumps : public Amesos_Mumps
    {
    public:
      using Amesos_Mumps::Amesos_Mumps;

      /// X = A^-1 B with the last factorisation; MUMPS's INFOG(1) (0 or
      /// positive: done), or -1 if the vectors could not be moved.
      int
      solve_columns(const Epetra_MultiVector &B, Epetra_MultiVector &X)
      {
        // MUMPS takes a centralised dense right-hand side on process 0.
        Epetra_MultiVector columns(SerialMap(), B.NumVectors());
        if (columns.Import(B, SerialImporter(), Insert) != 0)
          return -1;
        const int nrhs = MDS.nrhs, lrhs = MDS.lrhs;
        if (Comm().MyPID() == 0)
          {
            MDS.rhs  = columns.Values();
            MDS.nrhs = B.NumVectors();
            MDS.lrhs = columns.Stride();
          }
        MDS.job = 3;
        if (Comm().MyPID() < MaxProcs_)
          dmumps_c(&MDS);
        MDS.nrhs   = nrhs;
        MDS.lrhs   = lrhs;
        int status = MDS.infog[0];
        Comm().MinAll(&status, &status, 1);
        if (status < 0)
          return status;
        return X.Export(columns, SerialImporter(), Insert) == 0 ? 0 : -1;
      }
    };
  } // namespace
#endif

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
#ifdef HAVE_AMESOS_MUMPS
    if (solver_name == "Amesos_Mumps")
      solver = std::make_unique<MultiRhsMumps>(linear_problem);
    else
#endif
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

  void
  SparseDirectSolver::solve(const std::vector<TrilinosWrappers::MPI::Vector> &b,
                            std::vector<TrilinosWrappers::MPI::Vector>       &x)
  {
    AssertDimension(b.size(), x.size());
#ifdef HAVE_AMESOS_MUMPS
    if (auto *mumps = dynamic_cast<MultiRhsMumps *>(solver.get());
        mumps && b.size() > 1)
      {
        const Epetra_BlockMap &map = b[0].trilinos_vector().Map();
        const unsigned int     n   = map.NumMyPoints();
        Epetra_MultiVector     B(map, b.size()), X(map, b.size());
        for (unsigned int k = 0; k < b.size(); ++k)
          std::copy_n(b[k].trilinos_vector()[0], n, B[k]);
        AssertThrow(mumps->solve_columns(B, X) == 0,
                    ExcMessage("the sparse direct solve failed"));
        for (unsigned int k = 0; k < x.size(); ++k)
          std::copy_n(X[k], n, x[k].trilinos_vector()[0]);
        return;
      }
#endif
    for (unsigned int k = 0; k < b.size(); ++k)
      solve(b[k], x[k]);
  }
} // namespace rollnip
