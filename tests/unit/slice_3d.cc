// Stage 1 of the 3D body (three_d/slice_body.h): a slice of the cover with
// u_z = 0 on both faces is a plane-strain body, so its line load P(u0)
// against the rigid indenter must converge to the 2D P(u0) of the same
// scene. Truth: the 2D Q2-P1 solution at mesh level 3 on the nip-fitted
// mesh (Batra's inverse iteration, a different contact method, element
// and mesh; its own error is below 0.05 %, doc/accuracy.md). Also: a slice
// two cells thick gives the one-cell P to round-off (nothing varies along
// z), and u0 = 0 gives P = 0.

#include <deal.II/base/timer.h>

#include <rollnip/three_d/slice_body.h>

#include "test_tools.h"
#include "three_d_test_tools.h"

using namespace rollnip;

namespace
{
  const std::string scene =
    "subsection Geometry\n set Inner radius = 47.2\n set Outer radius = "
    "60.7\n set Sector angle = 90\nend\n"
    "subsection Mesh\n set Radial cells = 8\n set Circumferential cells = "
    "18\n set Circumferential grading = 10\nend\n"
    "subsection Material\n set C1 = 0.25\n set C2 = 0.25\nend\n"
    "subsection Boundary conditions\n set Far edge (id 3) = free\nend\n"
    "subsection Contact\n set Mode = indentation\n set Values = 0.5, 1, 2\n"
    " set Indenter radius = 76.2\nend\n";
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 check;
  const auto   parameters = testing::parameters_from_string(scene);
  const double u0[3]      = {0.5, 1., 2.};
  const double P_2d[3]    = {2.2103521, 6.3289393, 20.026731};

  const unsigned int levels[2] = {1, 2};
  double             error[2][3];
  double             P_one_layer = 0;
  for (unsigned int l = 0; l < 2; ++l)
    {
      three_d::SliceBody body(parameters,
                              testing::slice_parameters(1., 1),
                              levels[l],
                              MPI_COMM_WORLD);
      for (unsigned int k = 0; k < 3; ++k)
        {
          Timer                   timer;
          const three_d::SliceNip nip = body.solve(u0[k]);
          error[l][k]                 = nip.P / P_2d[k] - 1.;
          if (l == 0 && k == 1)
            P_one_layer = nip.P;
          std::cout << "level " << levels[l] << ", " << body.n_dofs()
                    << " DoFs, u0 = " << u0[k]
                    << " mm: P = " << std::setprecision(8) << nip.P
                    << " N/mm (2D " << P_2d[k] << ", error "
                    << testing::num(100 * error[l][k])
                    << " %), b = " << testing::num(nip.half_chord) << " mm, "
                    << nip.active_nodes << " active nodes, " << nip.newton_steps
                    << " Newton steps, " << testing::num(timer.wall_time())
                    << " s" << std::endl;
        }
    }
  for (unsigned int k = 0; k < 3; ++k)
    {
      const std::string at = "u0 = " + testing::num(u0[k]) + " mm: ";
      check.check(std::abs(error[0][k]) < 5e-3,
                  at + "level 1 P within 0.5 % of 2D: " +
                    testing::num(100 * error[0][k]) + " %");
      check.check(std::abs(error[1][k]) < 1.5e-3,
                  at + "level 2 P within 0.15 % of 2D: " +
                    testing::num(100 * error[1][k]) + " %");
      check.check(std::abs(error[1][k]) < 0.8 * std::abs(error[0][k]),
                  at + "the error falls with refinement, observed order " +
                    testing::num(std::log2(error[0][k] / error[1][k])));
    }

  // Nothing varies along z: two cells through the thickness give the
  // one-cell P to round-off.
  {
    three_d::SliceBody body(parameters,
                            testing::slice_parameters(1., 2),
                            levels[0],
                            MPI_COMM_WORLD);
    const double       P_two = body.solve(u0[1]).P;
    check.check(std::abs(P_two / P_one_layer - 1.) < 1e-8,
                "two cells thick against one at level 1, u0 = 1 mm: P " +
                  testing::num(P_two) + " against " +
                  testing::num(P_one_layer) + " N/mm, relative diff " +
                  testing::num(P_two / P_one_layer - 1.));
  }
  // No approach, no load.
  {
    three_d::SliceBody      body(parameters,
                            testing::slice_parameters(1., 1),
                            0,
                            MPI_COMM_WORLD);
    const three_d::SliceNip nip = body.solve(0.);
    check.check(nip.P == 0. && nip.active_nodes == 0,
                "u0 = 0: P = " + testing::num(nip.P) + " N/mm, " +
                  std::to_string(nip.active_nodes) + " active nodes");
  }
  return check.result();
}
