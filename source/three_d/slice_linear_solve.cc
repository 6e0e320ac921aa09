#include <rollnip/three_d/slice_body.h>

#include <sstream>

namespace rollnip
{
  namespace three_d
  {
    std::string
    SliceBody::linear_solver_name() const
    {
      const Parameters::LinearSolver &settings = parameters.linear_solver;
      std::ostringstream              name;
      if (iterative)
        name << "gmres-amg (GMRES to a relative residual of "
             << settings.iterative_tolerance
             << "; augmented Lagrangian, gamma = "
             << augmentation[parameters.material.n_layers() - 1].gamma
             << " MPa in the surface layer, each cell's from its own law;"
             << " AMG with the rigid-body modes on the displacements)";
      else
        name << "direct (" << direct->name()
             << ", the pattern analysed once, refactorised each Newton step)";
      return name.str();
    }

    void
    SliceBody::solve_linear(TrilinosWrappers::MPI::Vector &du)
    {
      if (iterative)
        {
          // K and the active set change every Newton step; the AMG
          // hierarchy is kept while it still serves (SliceBlockSolver).
          block_amg->initialize(system_matrix, preconditioner_matrix);
          block_amg->solve(system_rhs, du);
          return;
        }
      // The pattern of K is fixed (setup_system()): one analysis per body.
      direct->factorize(system_matrix);
      direct->solve(system_rhs, du);
    }
  } // namespace three_d
} // namespace rollnip
