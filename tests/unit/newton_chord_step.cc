// Newton's chord step (doc/intro.md, section 5) ends a solve whose
// residual and volume constraint are met but whose last update was not yet
// below Increment tolerance. Like the Newton iteration it replaces, it
// must leave the state far closer to the solution than its own update
// (the state's error before it): on the parabolic-pressure scene, with
// the tolerances a 1 % accuracy target sets (residual 1e-4, increment
// 1e-3, constraint 1e-5), the last load step ends with a chord step, and
// the state then differs from the same scene converged to round-off
// (residual 1e-12) by less than a hundredth of that step's update and
// less than the increment tolerance, with either linear solver; the two
// solvers take the same Newton iterations and chord steps.

#include <deal.II/base/mpi.h>

#include "test_tools.h"

using namespace rollnip;

namespace
{
  struct Result
  {
    TrilinosWrappers::MPI::Vector u;
    unsigned int                  newton, chords;
    double                        last_chord;
  };

  Result
  solve(const std::string &element,
        const std::string &method,
        const std::string &residual,
        const std::string &increment,
        const std::string &constraint)
  {
    const auto parameters = testing::parabolic_pressure_scene(
      element,
      method,
      "subsection Linear solver\n set Iterative tolerance = 1e-12\nend\n"
      "subsection Nonlinear solver\n set Residual tolerance = " +
        residual + "\n set Increment tolerance = " + increment +
        "\n set Constraint tolerance = " + constraint + "\nend\n");
    RollProblem problem(parameters, MPI_COMM_WORLD);
    problem.setup();
    problem.set_step_log(false);
    AssertThrow(problem.run().converged, ExcMessage("scene did not converge"));
    return {problem.owned_solution(),
            static_cast<unsigned int>(problem.newton_log().size()),
            problem.chord_steps(),
            problem.last_chord_update()};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  constexpr double                 increment_tolerance = 1e-3;
  for (const std::string element : {"Q1-P0", "Q2-P1"})
    {
      const Result exact = solve(element, "direct", "1e-12", "1e-12", "1e-13");
      for (const std::string method : {"direct", "gmres-amg"})
        {
          const Result loose = solve(element, method, "1e-4", "1e-3", "1e-5");
          TrilinosWrappers::MPI::Vector d(loose.u);
          d -= exact.u;
          const double      error = d.l2_norm() / exact.u.l2_norm();
          const std::string name  = element + ", " + method;
          std::cout << "  " << name << ": " << loose.newton
                    << " Newton iterations, " << loose.chords
                    << " chord steps; the last one's update "
                    << testing::num(loose.last_chord)
                    << ", then |u - u_exact| / |u_exact| = "
                    << testing::num(error)
                    << " (converged to round-off: " << exact.newton
                    << " iterations)" << std::endl;
          checker.check(loose.last_chord > 0,
                        name + ": the last solve ended with a chord step");
          checker.check(error < 1e-2 * loose.last_chord &&
                          error < increment_tolerance,
                        name +
                          ": the state after it is within 1e-2 of its "
                          "update and the increment tolerance of the "
                          "solution: " +
                          testing::num(error));
          if (method == "direct")
            continue;
          const Result direct =
            solve(element, "direct", "1e-4", "1e-3", "1e-5");
          checker.check(loose.newton == direct.newton &&
                          loose.chords == direct.chords,
                        name + ": the same Newton iterations (" +
                          std::to_string(loose.newton) + ", " +
                          std::to_string(direct.newton) +
                          ") and chord steps (" + std::to_string(loose.chords) +
                          ", " + std::to_string(direct.chords) +
                          ") as the direct solver");
        }
    }
  return checker.result();
}
