// The consistent tangent (doc/intro.md, sections 4 and 5):
// 1. Newton converges quadratically on a follower-pressure scene taken in
//    one load step: once the residual is small, e_{k+1} <= C e_k^2.
// 2. The assembled tangent equals a central finite-difference Jacobian of
//    the residual at a perturbed state, for the whole system and for the
//    follower-load part alone (R(lambda = 1) - R(lambda = 0)).

#include <deal.II/base/mpi.h>

#include <random>

#include "test_tools.h"

using namespace rollnip;

namespace
{
  const std::string scene =
    "subsection Mesh\n set Radial cells = 2\n set Circumferential cells = 6\n"
    " set Global refinements = 1\nend\n"
    "subsection Load\n set p0 = 0.6\n set theta0 = 15\nend\n"
    "subsection Load stepping\n set Initial steps = 1\n"
    " set Growth factor = 1\nend\n";

  /// K v, the residual-based finite difference and their relative mismatch.
  double
  tangent_mismatch(RollProblem                         &problem,
                   const TrilinosWrappers::MPI::Vector &state,
                   const TrilinosWrappers::MPI::Vector &direction,
                   const double                         lambda_a,
                   const double                         lambda_b,
                   double                              &norm_Kv)
  {
    const double h = 1e-6;
    // K(lambda_b) - K(lambda_a) applied to v.
    problem.set_solution(state);
    problem.assemble(lambda_b, true);
    TrilinosWrappers::MPI::Vector Kv(direction), tmp(direction);
    problem.tangent().vmult(Kv, direction);
    if (lambda_a >= 0)
      {
        problem.assemble(lambda_a, true);
        problem.tangent().vmult(tmp, direction);
        Kv -= tmp;
      }
    auto residual_at = [&](const double s) {
      TrilinosWrappers::MPI::Vector x(state);
      x.add(s, direction);
      problem.set_solution(x);
      problem.assemble(lambda_b, false);
      TrilinosWrappers::MPI::Vector r(problem.residual());
      if (lambda_a >= 0)
        {
          problem.assemble(lambda_a, false);
          r -= problem.residual();
        }
      return r;
    };
    TrilinosWrappers::MPI::Vector fd = residual_at(h);
    fd -= residual_at(-h);
    fd /= 2 * h;
    norm_Kv = Kv.l2_norm();
    fd -= Kv;
    problem.set_solution(state);
    return fd.l2_norm() / norm_Kv;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;

  const auto  parameters = testing::parameters_from_string(scene);
  RollProblem problem(parameters, MPI_COMM_WORLD);
  problem.setup();
  const RunStatus status = problem.run();
  checker.check(status.converged && problem.step_log().size() == 1,
                "the full load converged in one step");

  // 1. Quadratic convergence: every pair of iterates with e_k in
  //    [1e-12, 1e-2] satisfies e_{k+1} <= 10 e_k^2 / e_1 ... measured as the
  //    ratio log(e_{k+1}) / log(e_k) for the normalised residual.
  const auto  &log     = problem.newton_log();
  unsigned int n_pairs = 0;
  for (unsigned int k = 0; k + 1 < log.size(); ++k)
    {
      const double e0 = log[k].residual, e1 = log[k + 1].residual;
      std::cout << std::scientific << std::setprecision(3) << "  iteration "
                << log[k].iteration << ": e = " << e0 << " -> " << e1
                << std::endl;
      if (e0 > 1e-2 || e0 < 1e-7)
        continue;
      ++n_pairs;
      checker.check(e1 < 50 * e0 * e0,
                    "quadratic: e_{k+1} = " + testing::num(e1) +
                      " < 50 e_k^2 = " + testing::num(50 * e0 * e0));
    }
  checker.check(n_pairs >= 1,
                "at least one iterate in the quadratic range [1e-7, 1e-2]");

  // 2. Finite-difference check at a randomly perturbed converged state
  //    (perturbation satisfying the constraints, about 1 % of u).
  std::mt19937                           rng(42);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  TrilinosWrappers::MPI::Vector          state(
    problem.current_solution().locally_owned_elements(), MPI_COMM_WORLD);
  state                               = problem.current_solution();
  const double                  scale = state.linfty_norm();
  TrilinosWrappers::MPI::Vector direction(state), perturbation(state);
  for (const auto i : problem.locally_owned())
    {
      perturbation[i] = 0.01 * scale * uniform(rng);
      direction[i]    = scale * uniform(rng);
    }
  perturbation.compress(VectorOperation::insert);
  direction.compress(VectorOperation::insert);
  problem.constraints_object().set_zero(perturbation);
  problem.constraints_object().set_zero(direction);
  state += perturbation;

  double       norm_full, norm_load;
  const double full =
    tangent_mismatch(problem, state, direction, -1., 1., norm_full);
  const double load =
    tangent_mismatch(problem, state, direction, 0., 1., norm_load);
  checker.check(full < 1e-6,
                "full tangent vs finite differences: relative mismatch " +
                  testing::num(full) + " < 1e-6");
  checker.check(load < 1e-6,
                "follower-load stiffness vs finite differences: relative "
                "mismatch " +
                  testing::num(load) + " < 1e-6 (|K_load v| / |K v| = " +
                  testing::num(norm_load / norm_full) + ")");
  checker.check(norm_load > 1e-3 * norm_full,
                "the load stiffness is not negligible in this check");
  return checker.result();
}
