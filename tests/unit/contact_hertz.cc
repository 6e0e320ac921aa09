// Linear theory against Hertz (doc/intro.md section 7; physics.md section 8
// item 5): a thick cover (R1 = 5 mm, R0 = 60.7 mm, h = 55.7 mm) pressed by
// the Rbar = 76.2 mm cylinder at nips much smaller than h. For a rigid
// cylinder on an incompressible half-space in plane strain,
//   P = pi b^2 E* / (4 R),  E* = 4 G,  1/R = 1/R0 + 1/Rbar,
//   peak pressure 2 P / (pi b),
// with b the contact half-width. The finite thickness changes P by a
// relative amount of order (b/h)^2, below 1 % here (b/h <= 0.08), so P and
// the peak pressure must match to 1 % and 2 % (the peak sits on one node and
// carries more of the discretisation error).

#include <rollnip/contact/nip_study.h>

#include "test_tools.h"

using namespace rollnip;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  const auto                       parameters = testing::parameters_from_string(
    "subsection Geometry\n set Inner radius = 5\n set Outer radius = 60.7\n"
                          "end\n"
                          "subsection Mesh\n set Radial cells = 16\n set Radial grading = 0.05\n"
                          " set Circumferential cells = 48\n set Circumferential grading = 100\n"
                          " set Global refinements = 1\nend\n"
                          "subsection Material\n set Theory = linear\nend\n"
                          "subsection Contact\n set Mode = nip angle\n set Values = 2\n"
                          " set Indenter radius = 76.2\nend\n");
  RollProblem problem(parameters, MPI_COMM_WORLD);
  problem.setup();
  InverseContact contact(problem, parameters);
  const double   G = 2 * (parameters.material.C1 + parameters.material.C2);
  const double   R = 1. / (1. / 60.7 + 1. / 76.2);
  for (const double theta0_deg : {2., 4.})
    {
      const ContactResult r = contact.solve(theta0_deg * numbers::PI / 180);
      const double        b = r.half_chord;
      const double        P_hertz    = numbers::PI * b * b * 4 * G / (4 * R);
      const double        peak_hertz = 2 * r.nip_load / (numbers::PI * b);
      const std::string   at         = "theta0 = " + testing::num(theta0_deg) +
                             " deg (b/h = " + testing::num(b / 55.7) + "): ";
      checker.check(r.converged, at + "converged");
      checker.check(std::abs(r.nip_load / P_hertz - 1) < 0.01,
                    at + "P = " + testing::num(r.nip_load) + " N/mm, Hertz " +
                      testing::num(P_hertz) + " N/mm (ratio " +
                      testing::num(r.nip_load / P_hertz) + ", within 1 %)");
      checker.check(std::abs(r.peak_pressure / peak_hertz - 1) < 0.02,
                    at + "peak pressure " + testing::num(r.peak_pressure) +
                      " MPa, Hertz 2P/(pi b) = " + testing::num(peak_hertz) +
                      " MPa (within 2 %)");
    }
  return checker.result();
}
