// Stage 2 of the 3D body (three_d/free_end.h): a free cover end.
// Truths:
// - the decay measures of end_decay() on a sampled exponential fall
//   q = Q (1 - exp(-(L - z) / lambda)): the deficit length is lambda (up to
//   exp(-L / lambda) and the trapezoid error of the graded planes), the
//   95 % rise distance lambda ln 20;
// - graded layers with u_z = 0 on both faces are still plane strain: the
//   line load is the one-layer slice's P at every plane (1e-8) and the
//   deficit length 0;
// - far from a free end the line load is the plane-strain P of the same
//   cross-section mesh (within 0.3 % at 6.5 nip half-widths from the end),
//   and the line load integrates to the run's mean P (the nodal forces of
//   every plane, the tributary lengths summing to L);
// - at the middle plane z = 0 the bond stresses are those of the
//   plane-strain slice (within 1 %), and the end-face bulge is outwards.

#include <rollnip/three_d/free_end.h>

#include "test_tools.h"
#include "three_d_test_tools.h"

using namespace rollnip;

namespace
{
  const std::string scene = testing::thin_end_cover_scene();

  void
  check_decay_of_exponential(testing::Checker &check)
  {
    const double L = 40., lambda = 2., Q = 3.;
    const auto   z = three_d::axial_planes(L, 400, 20.);
    std::vector<std::pair<double, double>> profile;
    for (const double zj : z)
      profile.emplace_back(zj, Q * (1. - std::exp(-(L - zj) / lambda)));
    const three_d::EndDecay d = three_d::end_decay(profile);
    check.check(std::abs(d.deficit_length / lambda - 1.) < 1e-4,
                "exponential fall: deficit length " +
                  testing::num(d.deficit_length) + " mm, lambda " +
                  testing::num(lambda) + " mm");
    check.check(std::abs(d.rise_95 / (lambda * std::log(20.)) - 1.) < 1e-4,
                "exponential fall: 95 % rise " + testing::num(d.rise_95) +
                  " mm, lambda ln 20 = " +
                  testing::num(lambda * std::log(20.)) + " mm");
    const auto steps = three_d::axial_steps(L, 10, 20.);
    double     sum   = 0;
    for (const double s : steps)
      sum += s;
    check.check(std::abs(sum - L) < 1e-12 * L &&
                  std::abs(steps.front() / steps.back() - 20.) < 1e-10,
                "axial steps sum to L (" + testing::num(sum) +
                  " mm), first over last " +
                  testing::num(steps.front() / steps.back()));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 check;
  check_decay_of_exponential(check);
  const auto   parameters = testing::parameters_from_string(scene);
  const double u0         = 0.2;

  // The plane-strain slice: P and its bond stresses.
  three_d::SliceBody slice(parameters,
                           testing::slice_parameters(1., 1, false, 0.1),
                           0,
                           MPI_COMM_WORLD);
  const double       P_slice     = slice.solve(u0).P;
  const auto         slice_bond  = three_d::evaluate_free_end(slice, u0);
  const double       slice_shear = slice_bond.shear_middle.shear();

  // Graded layers, both faces axially fixed: still plane strain.
  {
    three_d::SliceBody body(parameters,
                            testing::slice_parameters(6., 6, false, 0.1, 8.),
                            0,
                            MPI_COMM_WORLD);
    body.solve(u0);
    double worst = 0;
    for (const auto &[z, q] : body.line_load_profile())
      worst = std::max(worst, std::abs(q / P_slice - 1.));
    check.check(worst < 1e-8,
                "graded plane strain: q(z) = slice P " + testing::num(P_slice) +
                  " N/mm at every plane, largest relative difference " +
                  testing::num(worst));
  }

  // The free end.
  const double            L = 30.;
  three_d::SliceBody      body(parameters,
                          testing::slice_parameters(L, 20, true, 0.1, 12.),
                          0,
                          MPI_COMM_WORLD);
  const three_d::SliceNip nip       = body.solve(u0);
  const three_d::FreeEnd  end       = three_d::evaluate_free_end(body, u0);
  const double            far_error = end.decay.q_far / P_slice - 1.;
  std::cout << "free end, L = " << L << " mm, " << body.n_dofs()
            << " DoFs: q(0) = " << testing::num(end.decay.q_far)
            << " N/mm, q(L) = " << testing::num(end.decay.q_end)
            << " N/mm, l = " << testing::num(end.decay.deficit_length)
            << " mm, 95 % rise " << testing::num(end.decay.rise_95)
            << " mm, bulge " << testing::num(end.bulge) << " mm" << std::endl;
  check.check(std::abs(far_error) < 3e-3,
              "far from the end q(0) = slice P within 0.3 %: " +
                testing::num(100 * far_error) + " %");
  check.check(std::abs(end.decay.q_mean / nip.P - 1.) < 1e-12,
              "the line load integrates to the mean P: " +
                testing::num(end.decay.q_mean) + " against " +
                testing::num(nip.P) + " N/mm");
  check.check(end.decay.q_end < 0.1 * end.decay.q_far &&
                end.decay.deficit_length > 0,
              "the line load falls at the end: q(L)/q(0) = " +
                testing::num(end.decay.q_end / end.decay.q_far));
  const double shear_error = end.shear_middle.shear() / slice_shear - 1.;
  check.check(std::abs(shear_error) < 1e-2,
              "bond shear at z = 0 " + testing::num(end.shear_middle.shear()) +
                " MPa, plane-strain slice " + testing::num(slice_shear) +
                " MPa");
  check.check(end.bulge > 0 && std::abs(end.bulge_at[2] - L) < 1e-12,
              "the end face bulges outwards: u_z = " + testing::num(end.bulge) +
                " mm on z = L");
  return check.result();
}
