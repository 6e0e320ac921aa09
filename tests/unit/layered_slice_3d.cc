// A layered cover in 3D (three_d/slice_mesh.h gives every cell its layer as
// material id, three_d/slice_body.h its layer's law): a slice one cell thick
// with u_z = 0 on both faces is a plane-strain body, so the P(u0) of a stiff
// 3.5 mm top on a soft 10 mm base must converge to the 2D P(u0) of the
// same two-layer scene, as slice_3d.cc checks for one layer. Truth: the 2D
// Q2-P1 solution at level 3 on the nip-fitted mesh (Batra's inverse
// iteration: another contact method, element and mesh), computed here.
// The stiff top must carry more load than the soft cover alone (slice_3d.cc's
// one-layer P), by far more than the discretisation error, so that a slice
// ignoring the top's law would fail.

#include <rollnip/contact/inverse_contact.h>
#include <rollnip/contact/nip_control.h>
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
    "subsection Material\n set Layer order = core first\n"
    " set C1 = 0.25, 1.25\n set C2 = 0.25, 0.25\n"
    " set Layer thicknesses = 10, 3.5\nend\n"
    "subsection Boundary conditions\n set Far edge (id 3) = free\nend\n"
    "subsection Contact\n set Mode = indentation\n set Values = 1\n"
    " set Indenter radius = 76.2\n set Conformity tolerance = 1e-8\n"
    " set Control tolerance = 1e-9\nend\n";

} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 check;
  const double                     u0 = 1.;
  const double P_2d       = testing::plane_strain_reference_load(scene, u0);
  const auto   parameters = testing::parameters_from_string(scene);
  double       error[2];
  for (const unsigned int level : {1u, 2u})
    {
      three_d::SliceBody      body(parameters,
                              testing::slice_parameters(1., 1),
                              level,
                              MPI_COMM_WORLD);
      const three_d::SliceNip nip = body.solve(u0);
      error[level - 1]            = nip.P / P_2d - 1.;
      std::cout << "two layers, level " << level << ", " << body.n_dofs()
                << " DoFs, u0 = 1 mm: P = " << std::setprecision(8) << nip.P
                << " N/mm (2D " << P_2d << ", error "
                << testing::num(100 * error[level - 1])
                << " %), b = " << testing::num(nip.half_chord) << " mm"
                << std::endl;
    }
  check.check(std::abs(error[0]) < 5e-3,
              "level 1 P within 0.5 % of 2D: " + testing::num(100 * error[0]) +
                " %");
  check.check(std::abs(error[1]) < 1.5e-3,
              "level 2 P within 0.15 % of 2D: " + testing::num(100 * error[1]) +
                " %");
  check.check(std::abs(error[1]) < 0.8 * std::abs(error[0]),
              "the error falls with refinement, observed order " +
                testing::num(std::log2(error[0] / error[1])));
  // slice_3d.cc's one-layer (soft, C1 = C2 = 0.25) 2D P(1 mm) = 6.329 N/mm.
  check.check(P_2d > 1.1 * 6.3289393,
              "the stiff top carries more load than the soft cover alone: "
              "P = " +
                testing::num(P_2d) + " N/mm (2D) against 6.329 N/mm");
  return check.result();
}
