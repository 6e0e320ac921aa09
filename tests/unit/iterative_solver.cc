// Linear solver/Method = gmres-amg solves the same Newton systems as the
// direct solver: on the parabolic-pressure scene, for both elements, the
// load resultant and the indentation agree to the GMRES tolerance, and
// Newton takes the same number of iterations (its convergence is not
// spoiled by inexact solves).

#include <deal.II/base/mpi.h>

#include "test_tools.h"

using namespace rollnip;

namespace
{
  struct Result
  {
    double       P, u0;
    unsigned int newton, gmres;
  };

  Result
  solve(const std::string &element, const std::string &method)
  {
    const auto  parameters = testing::parabolic_pressure_scene(element, method);
    RollProblem problem(parameters, MPI_COMM_WORLD);
    problem.setup();
    problem.set_step_log(false);
    AssertThrow(problem.run().converged, ExcMessage("scene did not converge"));
    const Result r{-problem.load_resultant(1.)[0],
                   -problem.radial_displacement_on_line_of_centres(),
                   static_cast<unsigned int>(problem.newton_log().size()),
                   problem.gmres_iterations()};
    std::cout << "  " << element << ", " << method << ": resultant "
              << std::setprecision(10) << r.P << " N/mm, u0 = " << r.u0
              << " mm, " << r.newton << " Newton iterations" << std::endl;
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  for (const std::string element : {"Q1-P0", "Q2-P1"})
    {
      const Result direct    = solve(element, "direct");
      const Result iterative = solve(element, "gmres-amg");
      const double dP        = std::abs(iterative.P - direct.P) / direct.P;
      const double du        = std::abs(iterative.u0 - direct.u0) / direct.u0;
      checker.check(dP < 1e-7 && du < 1e-7,
                    element + ": gmres-amg and direct agree: |dP|/P = " +
                      testing::num(dP) + ", |du0|/u0 = " + testing::num(du) +
                      " < 1e-7");
      checker.check(iterative.gmres > 0 && direct.gmres == 0,
                    element + ": GMRES ran (" +
                      std::to_string(iterative.gmres) +
                      " iterations) and the direct run used none");
      checker.check(iterative.newton == direct.newton,
                    element + ": same Newton iterations (" +
                      std::to_string(iterative.newton) + ", " +
                      std::to_string(direct.newton) + ")");
    }
  return checker.result();
}
