#ifndef rollnip_solvers_gmres_solve_h
#define rollnip_solvers_gmres_solve_h

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <rollnip/global.h>

#include <sstream>

namespace rollnip
{
  /**
   * x = K^-1 b by right-preconditioned GMRES (restart 100) from x = 0, to
   * the relative residual @p tolerance, for the block preconditioners of
   * the 2D and 3D bodies. Returns the iterations taken; if GMRES has not
   * converged in @p max_iterations, throws one line that names the
   * entries a user can change.
   */
  template <typename Preconditioner>
  unsigned int
  gmres_solve(const TrilinosWrappers::SparseMatrix &K,
              const Preconditioner                 &preconditioner,
              const TrilinosWrappers::MPI::Vector  &b,
              TrilinosWrappers::MPI::Vector        &x,
              const double                          tolerance,
              const unsigned int                    max_iterations)
  {
    x                    = 0;
    const double  b_norm = b.l2_norm();
    SolverControl control(max_iterations, tolerance * b_norm, false, false);
    SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData data;
    data.max_n_tmp_vectors     = 100;
    data.right_preconditioning = true;
    SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(control, data);
    try
      {
        gmres.solve(K, x, b, preconditioner);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        std::ostringstream what;
        what << "Linear solver/Method = gmres-amg: GMRES reached a relative "
             << "residual of " << e.last_residual / b_norm << " after "
             << e.last_step << " iterations (tolerance " << tolerance
             << "; Linear solver/Max iterations); use the direct method";
        AssertThrow(false, ExcMessage(what.str()));
      }
    return control.last_step();
  }
} // namespace rollnip

#endif
