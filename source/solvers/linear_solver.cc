#include <rollnip/solvers/linear_solver.h>

namespace rollnip
{
  LinearSolver::LinearSolver(const Parameters::LinearSolver &parameters,
                             ConditionalOStream             &pcout,
                             TimerOutput                    &timer)
      : iterative(parameters.method == "gmres-amg")
      , pcout(pcout)
      , timer(timer)
      , direct_solver(parameters.direct_solver)
      , iterative_solver(parameters.iterative_tolerance,
                         parameters.max_iterations)
  {}

  void
  LinearSolver::reinit(const RollBody &body, const bool new_pattern)
  {
    if (new_pattern)
      direct_solver.forget_pattern();
    if (!iterative)
      return;
    std::vector<std::vector<types::global_dof_index>> blocks;
    std::vector<FullMatrix<double>>                   inverses;
    body.pressure_mass_inverses(blocks, inverses);
    iterative_solver.set_schur_blocks(std::move(blocks), std::move(inverses));
  }

  void
  LinearSolver::factorize(const RollBody &body)
  {
    TimerOutput::Scope t(timer, "linear solve");
    ++factorization_count;
    if (iterative)
      {
        iterative_solver.initialize(body.tangent(),
                                    body.preconditioner(),
                                    body.displacement_modes(),
                                    body.fe().degree > 1);
        return;
      }
    const std::string before = direct_solver.name();
    direct_solver.factorize(body.tangent());
    if (direct_solver.name() != before)
      pcout << "      (" << before << " failed to factorise; switching to "
            << direct_solver.name() << ")" << std::endl;
  }

  void
  LinearSolver::solve(const RollBody                      &body,
                      const TrilinosWrappers::MPI::Vector &rhs,
                      TrilinosWrappers::MPI::Vector       &x)
  {
    TimerOutput::Scope t(timer, "linear solve");
    if (iterative)
      iterative_solver.solve(rhs, x);
    else
      direct_solver.solve(rhs, x);
    body.constraints().distribute(x);
  }

  void
  LinearSolver::solve(const RollBody                                   &body,
                      const std::vector<TrilinosWrappers::MPI::Vector> &rhs,
                      std::vector<TrilinosWrappers::MPI::Vector>       &x)
  {
    TimerOutput::Scope t(timer, "linear solve");
    if (iterative)
      for (unsigned int k = 0; k < rhs.size(); ++k)
        iterative_solver.solve(rhs[k], x[k]);
    else
      direct_solver.solve(rhs, x);
    for (auto &v : x)
      body.constraints().distribute(v);
  }
} // namespace rollnip
