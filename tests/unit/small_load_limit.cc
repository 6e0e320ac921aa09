// Limit 4 of doc/intro.md section 8: nonlinear results divided by the load
// tend to the linear theory's as the load tends to zero, and the difference
// is first order in the load. The scene is the default parabolic pressure
// on the roll cover; the linear theory has G = 2 (C1 + C2).
//
// Why C1 = 0: at F = I the nonlinear tangent is
//   G (dF + dF^T) - 2 C1 tr(dF) I + dq I,
// whose middle term vanishes in the continuum (tr dF = 0) but not with
// Q1-P0, which makes J = 1 hold only in the cell average. With C1 != 0 the
// difference therefore stalls at a discretisation-level value (0.13 % on
// this mesh with C1 = C2) instead of vanishing; that split effect is tested
// in mooney_rivlin_invariance. With C1 = 0 the discrete linearisation is
// exactly the linear theory and the load effect is seen alone.

#include "test_tools.h"

using namespace rollnip;

namespace
{
  std::vector<OuterSurfacePoint>
  solve(const std::string &theory, const double p0)
  {
    const auto parameters = testing::parameters_from_string(
      "subsection Mesh\n set Radial cells = 3\n set Circumferential cells = "
      "12\n"
      " set Global refinements = 1\nend\n"
      "subsection Material\n set C1 = 0\n set C2 = 0.5\n set Theory = " +
      theory +
      "\nend\n"
      "subsection Load stepping\n set Initial steps = 1\nend\n"
      "subsection Load\n set p0 = " +
      testing::num(p0) + "\n set theta0 = 12\nend\n");
    RollProblem problem(parameters, MPI_COMM_WORLD);
    problem.setup();
    AssertThrow(problem.run().converged, ExcMessage("no convergence"));
    return problem.surface_data(1.).outer;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  // Linear theory is linear: solve once at p0 = 1 MPa and scale.
  const auto          linear = solve("linear", 1.);
  std::vector<double> errors;
  // The last two are far below the residual tolerance's reach relative to
  // the stresses' round-off (p0/G = 1e-6, 1e-8): the Newton test adds the
  // round-off floor, so they converge, and the difference keeps falling
  // with the load.
  const std::vector<double> loads = {0.04, 0.02, 0.01, 0.005, 1e-6, 1e-8};
  for (const double p0 : loads)
    {
      const auto nonlinear = solve("nonlinear", p0);
      double     diff = 0, norm = 0;
      for (unsigned int i = 0; i < linear.size(); ++i)
        {
          diff += std::pow(nonlinear[i].u_r / p0 - linear[i].u_r, 2) +
                  std::pow(nonlinear[i].u_theta / p0 - linear[i].u_theta, 2);
          norm += std::pow(linear[i].u_r, 2) + std::pow(linear[i].u_theta, 2);
        }
      errors.push_back(std::sqrt(diff / norm));
      std::cout << std::defaultfloat << std::setprecision(4) << "p0 = " << p0
                << " MPa: |u_NL/p0 - u_L| / |u_L| on the outer surface = "
                << errors.back() << std::endl;
    }
  for (unsigned int k = 1; k < 4; ++k)
    {
      const double ratio = errors[k - 1] / errors[k];
      checker.check(ratio > 1.8 && ratio < 2.2,
                    "halving the load halves the difference: ratio " +
                      testing::num(ratio) + " in [1.8, 2.2]");
    }
  checker.check(errors[3] < 0.01,
                "at p0 = 0.005 MPa (p0/G = 0.005) the difference " +
                  testing::num(errors[3]) + " < 1 %");
  // First order down to p0/G = 1e-6 (0.005 MPa's difference, 3.5e-4,
  // times 2e-4 is 7.0e-8; measured 7.0e-8). At 1e-8 the stresses'
  // round-off, not the load, sets the difference (2.8e-8): still converged
  // and far below any discretisation error.
  checker.check(errors[4] < 2 * errors[3] * 1e-6 / 0.005 && errors[5] < 1e-6,
                "tiny loads converge and approach the linear theory: "
                "difference " +
                  testing::num(errors[4]) + " at p0 = 1e-6 MPa, " +
                  testing::num(errors[5]) + " at 1e-8 MPa");
  return checker.result();
}
