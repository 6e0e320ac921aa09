// The compressible cover in 3D (three_d/slice_body.h, the law from
// make_layer_law<3>()): a slice one cell thick with u_z = 0 on both faces is
// a plane-strain body, so with Poisson ratio 0.45 its P(u0) must converge to
// the 2D P(u0) of the same compressible scene, as slice_3d.cc checks for the
// incompressible cover. Truth: the 2D Q2-P1 solution at level 3 on the
// nip-fitted mesh (Batra's inverse iteration: another contact method,
// element and mesh), computed here. The compressible cover must also need
// less load than the incompressible one for the same approach.

#include <rollnip/contact/inverse_contact.h>
#include <rollnip/contact/nip_control.h>
#include <rollnip/three_d/slice_body.h>

#include "test_tools.h"
#include "three_d_test_tools.h"

using namespace rollnip;

namespace
{
  std::string
  scene(const double nu)
  {
    return testing::compressible_quarter_scene(nu) +
           "subsection Contact\n set Conformity tolerance = 1e-8\n"
           " set Control tolerance = 1e-9\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 check;
  const double                     nu = 0.45, u0 = 1.;
  const double P_2d       = testing::plane_strain_reference_load(scene(nu), u0);
  const auto   parameters = testing::parameters_from_string(scene(nu));
  double       error[2];
  double       P_slice = 0;
  for (const unsigned int level : {1u, 2u})
    {
      three_d::SliceBody      body(parameters,
                              testing::slice_parameters(1., 1),
                              level,
                              MPI_COMM_WORLD);
      const three_d::SliceNip nip = body.solve(u0);
      error[level - 1]            = nip.P / P_2d - 1.;
      P_slice                     = nip.P;
      std::cout << "nu = 0.45, level " << level << ", " << body.n_dofs()
                << " DoFs, u0 = 1 mm: P = " << std::setprecision(8) << nip.P
                << " N/mm (2D " << P_2d << ", error "
                << testing::num(100 * error[level - 1])
                << " %), b = " << testing::num(nip.half_chord) << " mm"
                << std::endl;
    }
  // Unlike the incompressible slice (0.5 % and 0.15 % off at levels 1
  // and 2, slice_3d.cc), the compressible one is within 0.03 % of 2D
  // already at level 1 and changes by 4e-5 to level 2: the difference is
  // at the level of the 2D reference's own error, so no falling error is
  // asserted, only agreement and a converged slice.
  check.check(std::abs(error[0]) < 1e-3 && std::abs(error[1]) < 1e-3,
              "nu = 0.45, slice P within 0.1 % of 2D at levels 1 and 2: " +
                testing::num(100 * error[0]) + " %, " +
                testing::num(100 * error[1]) + " %");
  check.check(std::abs((1 + error[1]) / (1 + error[0]) - 1) < 2e-4,
              "the slice is converged: level 1 to 2 changes P by " +
                testing::num(100 * ((1 + error[1]) / (1 + error[0]) - 1)) +
                " %");
  // slice_3d.cc's incompressible 2D P(1 mm) = 6.3289393 N/mm.
  check.check(P_slice < 6.3289393 && P_2d < 6.3289393,
              "the compressible cover needs less load: P = " +
                testing::num(P_slice) + " (3D), " + testing::num(P_2d) +
                " (2D) < 6.329 N/mm (incompressible)");
  return check.result();
}
