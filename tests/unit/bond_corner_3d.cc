// The bond traction at the bonded corner of a free cover end
// (three_d/free_end.h, FreeEnd::corner_sigma_rr): the corner is singular,
// so the nodal peak grows as the end layers are refined, while the
// tent-weighted mean over a length h (the cover thickness) converges.
// Truth: the refinement sequence itself, 10, 20 and 40 layers graded 12
// times towards the end (each halving the end layer): the change of the
// mean must shrink at least by half from one halving to the next, and the
// mean must stay between the compressive nodal peak and zero, while that
// peak grows by over 40 % over the last halving.

#include <rollnip/three_d/free_end.h>

#include "test_tools.h"
#include "three_d_test_tools.h"

using namespace rollnip;

namespace
{
  const std::string scene = testing::thin_end_cover_scene();
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 check;
  const auto         parameters = testing::parameters_from_string(scene);
  const unsigned int layers[3]  = {10, 20, 40};
  double             mean[3], peak[3];
  for (unsigned int k = 0; k < 3; ++k)
    {
      const auto t = testing::slice_parameters(30., layers[k], true, 0.1, 12.);
      three_d::SliceBody body(parameters, t, 0, MPI_COMM_WORLD);
      body.solve(0.2);
      const three_d::FreeEnd end = three_d::evaluate_free_end(body, 0.2);
      mean[k]                    = end.corner_sigma_rr[1];
      peak[k]                    = end.compression_peak.sigma_rr;
      std::cout << layers[k] << " layers: corner sigma_rr mean over h "
                << testing::num(mean[k]) << " MPa (over h/2 "
                << testing::num(end.corner_sigma_rr[0]) << "), tau_rz mean "
                << testing::num(end.corner_tau_rz[1]) << " MPa, nodal peak "
                << testing::num(peak[k]) << " MPa" << std::endl;
    }
  const double d1 = mean[1] - mean[0], d2 = mean[2] - mean[1];
  check.check(std::abs(d2) < 0.5 * std::abs(d1),
              "the corner mean converges: changes " + testing::num(d1) +
                " then " + testing::num(d2) + " MPa");
  check.check(mean[2] < 0 && mean[2] > peak[2],
              "the mean " + testing::num(mean[2]) +
                " MPa is compressive, above the nodal peak " +
                testing::num(peak[2]) + " MPa");
  check.check(peak[2] < 1.4 * peak[1],
              "the nodal peak grows with the layers: " + testing::num(peak[1]) +
                " then " + testing::num(peak[2]) + " MPa");
  return check.result();
}
