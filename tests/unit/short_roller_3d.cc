// Stage 4 of the 3D body: a short roller on a flat. The Batra (1980)
// cover on a rigid core pressed onto a rigid plane (Contact/Indenter radius
// = inf). Truths:
// - the plane-strain slice (u_z = 0 on both faces) against the plane gives
//   the 2D P(u0) of the same scene to the level-0 discretisation error
//   (2D reference: Q2-P1 at level 2 on the nip-fitted mesh, Batra's
//   inverse iteration, P = 2.947908 and 9.147509 N/mm at u0 = 0.5, 1 mm,
//   peak pressure 0.5563 MPa at 1 mm);
// - a roller 20 mm wide (the plane-strain nip is 21.6 mm wide) with free
//   cover ends carries less: its line load falls monotonically from the
//   middle to the end, the middle's stays below plane strain, and so do
//   the mean line load and the peak pressure.

#include <rollnip/three_d/slice_body.h>

#include "test_tools.h"
#include "three_d_test_tools.h"

#include <cmath>

using namespace rollnip;

namespace
{
  const std::string scene = testing::run30_indentation_scene("1", "inf");

  Parameters::ThreeD
  roller(const double half_width, const unsigned int layers, const bool free)
  {
    auto t            = testing::slice_parameters(half_width, layers, free);
    t.core_deflection = "0";
    return t;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 check;
  const auto   parameters = testing::parameters_from_string(scene);
  const double u0[2]      = {0.5, 1.};
  const double P_2d[2]    = {2.947908, 9.147509};

  three_d::SliceBody slice(parameters, roller(1, 1, false), 0, MPI_COMM_WORLD);
  three_d::SliceNip  plane_strain;
  for (unsigned int k = 0; k < 2; ++k)
    {
      plane_strain = slice.solve(u0[k]);
      check.check(std::abs(plane_strain.P / P_2d[k] - 1) < 0.02,
                  "plane-strain slice on the plane, u0 = " +
                    testing::num(u0[k]) +
                    " mm: P = " + testing::num(plane_strain.P) + " N/mm, 2D " +
                    testing::num(P_2d[k]) + " N/mm (" +
                    testing::num(100 * (plane_strain.P / P_2d[k] - 1)) +
                    " %, level 0)");
    }
  const three_d::ContactPatch long_patch = slice.contact_patch();
  check.check(std::abs(long_patch.peak_pressure / 0.5563 - 1) < 0.03,
              "plane-strain peak pressure " +
                testing::num(long_patch.peak_pressure) +
                " MPa against the 2D 0.5563 MPa");

  three_d::SliceBody          short_roller(parameters,
                                  roller(10, 10, true),
                                  0,
                                  MPI_COMM_WORLD);
  const three_d::SliceNip     nip   = short_roller.solve(1.);
  const three_d::ContactPatch patch = short_roller.contact_patch();
  const auto                  q =
    three_d::consistent_line_load(short_roller.line_load_profile());
  bool falling = true;
  for (unsigned int j = 1; j < q.size(); ++j)
    falling = falling && q[j].second < q[j - 1].second;
  std::cout << "short roller, 20 mm wide, u0 = 1 mm: mean line load "
            << testing::num(nip.P) << " N/mm, middle "
            << testing::num(patch.line_load_middle) << " N/mm, end "
            << testing::num(q.back().second) << " N/mm, peak pressure "
            << testing::num(patch.peak_pressure) << " MPa, half-chords "
            << testing::num(patch.half_chord_middle) << " (middle), "
            << testing::num(patch.half_chord_far) << " mm (end)" << std::endl;
  check.check(falling, "the line load falls from the middle to the free end");
  check.check(nip.P < patch.line_load_middle &&
                patch.line_load_middle < plane_strain.P,
              "mean " + testing::num(nip.P) + " < middle " +
                testing::num(patch.line_load_middle) + " < plane strain " +
                testing::num(plane_strain.P) + " N/mm");
  check.check(patch.peak_pressure < long_patch.peak_pressure,
              "peak pressure " + testing::num(patch.peak_pressure) +
                " MPa below plane strain " +
                testing::num(long_patch.peak_pressure) + " MPa");
  return check.result();
}
