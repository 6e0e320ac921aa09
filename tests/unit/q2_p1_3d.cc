// The 3D body with Discretization/Element = Q2-P1 (three_d/slice_body.h).
// Truths:
// - stage 1: the plane-strain slice's P(u0) converges to the 2D Q2-P1
//   P(u0) of the same cross-section (level 3 on the nip-fitted mesh,
//   Batra's inverse iteration; its estimated error is below 1e-5 of P),
//   at an observed order above 1.4 over levels 0 and 1, and on the same
//   mesh Q2-P1 is at least twice as close to it as Q1-P0 (the other
//   family);
// - the lumped line load of a state uniform along z is the same at the
//   vertex and the mid-layer planes (the weights h/6, 2h/3, h/6 are the
//   row sums the nodal forces carry);
// - the free cover end: far from the end Q2-P1's q agrees with Q1-P0's
//   within Q1-P0's own error there (its plane-strain slice against the
//   2D P), and the line load integrates to the mean P.

#include <rollnip/three_d/free_end.h>

#include "test_tools.h"
#include "three_d_test_tools.h"

using namespace rollnip;

namespace
{
  const std::string slice_scene =
    "subsection Geometry\n set Inner radius = 47.2\n set Outer radius = "
    "60.7\n set Sector angle = 90\nend\n"
    "subsection Mesh\n set Radial cells = 8\n set Circumferential cells = "
    "18\n set Circumferential grading = 10\nend\n"
    "subsection Material\n set C1 = 0.25\n set C2 = 0.25\nend\n"
    "subsection Boundary conditions\n set Far edge (id 3) = free\nend\n"
    "subsection Contact\n set Mode = indentation\n set Values = 0.5, 1\n"
    " set Indenter radius = 76.2\nend\n";

  const std::string end_scene = testing::thin_end_cover_scene();

  Parameters::AllParameters
  with_element(const std::string &scene, const std::string &element)
  {
    return testing::parameters_from_string(
      scene + "subsection Discretization\n set Element = " + element +
      "\nend\n");
  }

  void
  check_slice(testing::Checker &check)
  {
    const double u0[2]   = {0.5, 1.};
    const double P_2d[2] = {2.210352103, 6.328938794};
    const auto   q2      = with_element(slice_scene, "Q2-P1");
    const auto   q1      = with_element(slice_scene, "Q1-P0");
    double       error[2][2], error_q1[2];
    for (unsigned int level = 0; level < 2; ++level)
      {
        three_d::SliceBody body(q2,
                                testing::slice_parameters(1, 1),
                                level,
                                MPI_COMM_WORLD);
        three_d::SliceBody other(q1,
                                 testing::slice_parameters(1, 1),
                                 level,
                                 MPI_COMM_WORLD);
        for (unsigned int k = 0; k < 2; ++k)
          {
            error[level][k] = body.solve(u0[k]).P / P_2d[k] - 1.;
            if (level == 1)
              error_q1[k] = other.solve(u0[k]).P / P_2d[k] - 1.;
            std::cout << "Q2-P1 level " << level << ", " << body.n_dofs()
                      << " DoFs, u0 = " << u0[k] << " mm: P error "
                      << testing::num(100 * error[level][k]) << " %"
                      << std::endl;
          }
        if (level == 1)
          {
            // u0 = 1 mm: uniform along z, lumped q the same at all planes.
            const auto profile = body.line_load_profile();
            double     spread  = 0;
            for (const auto &[z, q] : profile)
              spread = std::max(spread, std::abs(q / profile[0].second - 1.));
            check.check(profile.size() == 3 && spread < 1e-8,
                        "Q2 slice: lumped q at the 3 node planes equal, "
                        "largest relative difference " +
                          testing::num(spread));
          }
      }
    for (unsigned int k = 0; k < 2; ++k)
      {
        const std::string at    = "u0 = " + testing::num(u0[k]) + " mm: ";
        const double      order = std::log2(error[0][k] / error[1][k]);
        check.check(std::abs(error[1][k]) < 1e-3,
                    at + "Q2-P1 level 1 P within 0.1 % of 2D: " +
                      testing::num(100 * error[1][k]) + " %");
        check.check(order > 1.4,
                    at + "Q2-P1 observed order over levels 0, 1 above 1.4: " +
                      testing::num(order));
        check.check(std::abs(error[1][k]) < 0.5 * std::abs(error_q1[k]),
                    at + "Q2-P1 error " + testing::num(100 * error[1][k]) +
                      " % under half Q1-P0's " +
                      testing::num(100 * error_q1[k]) + " % on level 1");
      }
  }

  void
  check_free_end(testing::Checker &check)
  {
    const double u0 = 0.2, L = 30.;
    double       q_far[2], P_slice[2];
    const char  *names[2] = {"Q1-P0", "Q2-P1"};
    for (unsigned int e = 0; e < 2; ++e)
      {
        const auto         prm = with_element(end_scene, names[e]);
        three_d::SliceBody slice(prm,
                                 testing::slice_parameters(1, 1, false, 0.1),
                                 0,
                                 MPI_COMM_WORLD);
        P_slice[e] = slice.solve(u0).P;
        three_d::SliceBody body(
          prm,
          testing::slice_parameters(L, 20, true, 0.1, 12.),
          0,
          MPI_COMM_WORLD);
        const three_d::SliceNip nip = body.solve(u0);
        const three_d::FreeEnd  end = three_d::evaluate_free_end(body, u0);
        q_far[e]                    = end.decay.q_far;
        std::cout << names[e] << " free end, " << body.n_dofs()
                  << " DoFs: q(0) = " << testing::num(end.decay.q_far)
                  << " N/mm, slice P = " << testing::num(P_slice[e])
                  << " N/mm, l = " << testing::num(end.decay.deficit_length)
                  << " mm, 95 % rise " << testing::num(end.decay.rise_95)
                  << " mm, bulge " << testing::num(end.bulge) << " mm"
                  << std::endl;
        check.check(std::abs(end.decay.q_mean / nip.P - 1.) < 1e-12,
                    std::string(names[e]) +
                      ": the line load integrates to the mean P: " +
                      testing::num(end.decay.q_mean) + " against " +
                      testing::num(nip.P) + " N/mm");
      }
    // Q1-P0's error: its slice against Q2-P1's (the finer family).
    const double q1_error = std::abs(P_slice[0] / P_slice[1] - 1.);
    const double diff     = std::abs(q_far[1] / q_far[0] - 1.);
    check.check(diff < 1.5 * q1_error,
                "free end: Q2-P1 q(0) " + testing::num(q_far[1]) +
                  " against Q1-P0 " + testing::num(q_far[0]) +
                  " N/mm, relative difference " + testing::num(diff) +
                  ", Q1-P0's slice error " + testing::num(q1_error));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 check;
  check_slice(check);
  check_free_end(check);
  return check.result();
}
