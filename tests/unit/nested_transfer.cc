// The displacement carried from one mesh level to another
// (transfer_nested_displacement(), which starts the error estimate's
// companion from the answer), for Q1-P0 and Q2-P1 on the nip-fitted mesh:
//
// 1. Down and back: a field on level 0 carried to level 1 and back to
//    level 0 is the field itself (every level-0 node is a level-1 node,
//    and a finer field that is the coarser one's prolongation restricts to
//    it): to round-off.
// 2. Two ways to level 2: level 0 -> 2 directly and 0 -> 1 -> 2 agree (the
//    path to the coarse cell and the descent into the other mesh must name
//    the same children), to round-off.
// 3. A solved nip: the level-0 answer on level 1 has u0 (a node of both)
//    to round-off, and Newton from it carries the same pressure in fewer
//    iterations than from the unloaded cover.

#include <deal.II/base/mpi.h>

#include <rollnip/body/nested_transfer.h>
#include <rollnip/contact/inverse_contact.h>

#include "test_tools.h"

#include <cmath>

using namespace rollnip;

namespace
{
  std::string
  scene(const std::string &element, const unsigned int level)
  {
    return "subsection Geometry\n set Inner radius = 47.2\n"
           " set Outer radius = 60.7\n set Sector angle = 90\nend\n"
           "subsection Mesh\n set Radial cells = 8\n"
           " set Circumferential cells = 18\n set Global refinements = " +
           std::to_string(level) +
           "\nend\n"
           "subsection Discretization\n set Element = " +
           element +
           "\nend\n"
           "subsection Material\n set C1 = 0.25\n set C2 = 0.25\nend\n"
           "subsection Boundary conditions\n"
           " set Inner arc (id 0) = fixed\n"
           " set Outer arc (id 1) = pressure\n"
           " set Symmetry edge (id 2) = symmetry\n"
           " set Far edge (id 3) = free\nend\n"
           "subsection Contact\n set Mode = nip angle\n set Values = 6\n"
           " set Indenter radius = 76.2\nend\n";
  }

  /// A smooth field on the displacement DoFs of @p problem: each node's
  /// value from its DoF index, so that any mix-up of nodes shows.
  void
  fill(RollProblem &problem)
  {
    TrilinosWrappers::MPI::Vector v(problem.owned_solution());
    for (const auto i : problem.locally_owned())
      v[i] = problem.body().pressure_dofs().is_element(i)
               ? 0.
               : std::sin(0.37 * i) + 0.01 * i;
    v.compress(VectorOperation::insert);
    problem.constraints_object().distribute(v);
    problem.set_solution(v);
  }

  /// max |a - b| over the displacement DoFs.
  double
  displacement_difference(const RollProblem &a, const RollProblem &b)
  {
    double d = 0;
    for (const auto i : a.locally_owned())
      if (!a.body().pressure_dofs().is_element(i))
        d =
          std::max(d, std::abs(a.owned_solution()[i] - b.owned_solution()[i]));
    return d;
  }

  void
  check_fields(testing::Checker &checker, const std::string &element)
  {
    const auto  p0 = testing::parameters_from_string(scene(element, 0));
    const auto  p1 = testing::parameters_from_string(scene(element, 1));
    const auto  p2 = testing::parameters_from_string(scene(element, 2));
    RollProblem level0(p0, MPI_COMM_WORLD), back(p0, MPI_COMM_WORLD),
      level1(p1, MPI_COMM_WORLD), direct(p2, MPI_COMM_WORLD),
      stepwise(p2, MPI_COMM_WORLD);
    for (RollProblem *r : {&level0, &back, &level1, &direct, &stepwise})
      r->setup();
    fill(level0);
    const double scale = level0.owned_solution().linfty_norm();
    const bool   done =
      transfer_nested_displacement(level0.body(), level1.body()) &&
      transfer_nested_displacement(level1.body(), back.body());
    checker.check(done, element + ": the meshes nest");
    const double round_trip = displacement_difference(level0, back) / scale;
    checker.check(round_trip < 1e-12,
                  element + ": level 0 -> 1 -> 0 gives the field back (" +
                    testing::num(round_trip) + " < 1e-12)");
    transfer_nested_displacement(level0.body(), direct.body());
    transfer_nested_displacement(level1.body(), stepwise.body());
    const double paths = displacement_difference(direct, stepwise) / scale;
    checker.check(paths < 1e-12,
                  element + ": level 0 -> 2 and 0 -> 1 -> 2 agree (" +
                    testing::num(paths) + " < 1e-12)");
  }

  /// Newton iterations of the last run of @p problem.
  unsigned int
  newton_iterations(const RollProblem &problem, const std::size_t before)
  {
    return problem.newton_log().size() - before;
  }

  void
  check_nip(testing::Checker &checker, const std::string &element)
  {
    const auto  p0 = testing::parameters_from_string(scene(element, 0));
    const auto  p1 = testing::parameters_from_string(scene(element, 1));
    RollProblem coarse(p0, MPI_COMM_WORLD), warm(p1, MPI_COMM_WORLD),
      cold(p1, MPI_COMM_WORLD);
    for (RollProblem *r : {&coarse, &warm, &cold})
      r->setup();
    InverseContact      contact(coarse, p0);
    const ContactResult r = contact.solve(6 * numbers::PI / 180);
    checker.check(r.converged, element + ": the level-0 nip converges");
    transfer_nested_displacement(coarse.body(), warm.body());
    const double u0_coarse = coarse.radial_displacement_on_line_of_centres();
    const double u0_warm   = warm.radial_displacement_on_line_of_centres();
    checker.check(std::abs(u0_warm / u0_coarse - 1) < 1e-12,
                  element + ": u0 carried over (" + testing::num(u0_coarse) +
                    " and " + testing::num(u0_warm) + " mm)");
    // The level-0 contact pressure on the level-1 cover, from the carried
    // state and from the unloaded one.
    const auto pressure = contact.last_converged().pressure;
    for (RollProblem *fine : {&warm, &cold})
      {
        fine->fit_mesh_to_nip(r.theta0);
        fine->set_pressure([pressure](const double theta, const double) {
          return pressure(theta);
        });
        fine->set_step_log(false);
      }
    const std::size_t  n_warm = warm.newton_log().size();
    const RunStatus    s_warm = warm.run(true, 1.);
    const unsigned int i_warm = newton_iterations(warm, n_warm);
    const RunStatus    s_cold = cold.run(false);
    const unsigned int i_cold = newton_iterations(cold, 0);
    const double       u_w    = warm.radial_displacement_on_line_of_centres();
    const double       u_c    = cold.radial_displacement_on_line_of_centres();
    checker.check(s_warm.converged && s_cold.converged &&
                    std::abs(u_w / u_c - 1) < 1e-8,
                  element +
                    ": from the carried state and from rest, the same "
                    "u0 under the level-0 pressure (" +
                    testing::num(u_w) + ", " + testing::num(u_c) + " mm)");
    checker.check(i_warm <= 4 && i_warm < i_cold,
                  element + ": Newton from the carried state in " +
                    std::to_string(i_warm) + " iterations (<= 4), from rest " +
                    std::to_string(i_cold));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  for (const std::string element : {"Q1-P0", "Q2-P1"})
    {
      check_fields(checker, element);
      check_nip(checker, element);
    }
  return checker.result();
}
