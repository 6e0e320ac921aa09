#include <deal.II/base/exceptions.h>

#include <rollnip/output/silence_cerr.h>
#include <rollnip/solvers/sparse_direct.h>

#include <Amesos.h>
#include <Amesos_config.h>
#include <Epetra_MultiVector.h>
#include <Epetra_Vector.h>
#ifdef HAVE_AMESOS_MUMPS
#include <Amesos_Mumps.h>
#endif

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

      /// x[k] = A^-1 b[k] with the last factorisation; MUMPS's INFOG(1)
      /// (0 or positive: done), or -1 if the vectors could not be moved.
      int
      solve_columns(const std::vector<TrilinosWrappers::MPI::Vector> &b,
                    std::vector<TrilinosWrappers::MPI::Vector>       &x)
      {
        // MUMPS takes a centralised dense right-hand side on process 0.
        Epetra_MultiVector columns(SerialMap(), b.size());
        for (unsigned int k = 0; k < b.size(); ++k)
          {
            Epetra_Vector column(View, columns, k);
            if (column.Import(b[k].trilinos_vector(),
                              SerialImporter(),
                              Insert) != 0)
              return -1;
          }
        const bool host = Comm().MyPID() == 0;
        const int  nrhs = host ? MDS.nrhs : 0, lrhs = host ? MDS.lrhs : 0;
        if (host)
          {
            MDS.rhs  = columns.Values();
            MDS.nrhs = b.size();
            MDS.lrhs = columns.Stride();
          }
        // Processes outside MUMPS's communicator have no status of theirs.
        int status = 0;
        if (Comm().MyPID() < MaxProcs_)
          {
            MDS.job = 3;
            dmumps_c(&MDS);
            status = MDS.infog[0];
          }
        if (host)
          {
            MDS.rhs  = nullptr;
            MDS.nrhs = nrhs;
            MDS.lrhs = lrhs;
          }
        int worst = 0;
        Comm().MinAll(&status, &worst, 1);
        if (worst < 0)
          return worst;
        for (unsigned int k = 0; k < x.size(); ++k)
          {
            Epetra_Vector column(View, columns, k);
            if (x[k].trilinos_vector().Export(column,
                                              SerialImporter(),
                                              Insert) != 0)
              return -1;
          }
        return 0;
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
    // Where MUMPS fails on all at once (its workspace for many columns,
    // say), one at a time, as Amesos does.
    if (auto *mumps = dynamic_cast<MultiRhsMumps *>(solver.get());
        mumps && b.size() > 1 && mumps->solve_columns(b, x) == 0)
      return;
#endif
    for (unsigned int k = 0; k < b.size(); ++k)
      solve(b[k], x[k]);
  }
} // namespace rollnip
