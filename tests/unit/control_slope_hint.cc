// Load and indentation control started from a coarser mesh's nip (the
// error estimate's coarser companion leads the run: NipControl::solve()
// with a guess and its slope) takes that slope for its second step while
// one nip of the target has converged, not the chord or the quadratic
// through the nips of earlier targets, which miss the local slope by the
// curve's bend over that span. On a curve u0(theta0) known in closed form
// (log u0 quadratic in log theta0: slope 1.7 + 0.8 log(theta0 / 0.1)), a
// sweep of indentations 0.5, 1, 2, 3 mm, each started 2e-4 off in u0:
//  - with the exact slope there, every answer lies within the control
//    tolerance (1e-6) of its target and every target takes 2 solves;
//  - with the same guesses and no slope, the second target takes 3 (its
//    second step follows the chord from the first target's nip: measured
//    3, 3, 3, 2 solves), so the check above can fail.

#include <rollnip/contact/nip_control.h>
#include <rollnip/contact/nip_solver.h>
#include <rollnip/scene/scene_description.h>

#include "test_tools.h"

#include <cmath>

using namespace rollnip;

namespace
{
  /// log u0 = log u_ref + s x + c x^2 with x = log(theta0 / theta_ref).
  constexpr double theta_ref = 0.1, u_ref = 1., s = 1.7, c = 0.4;

  double
  indentation(const double theta0)
  {
    const double x = std::log(theta0 / theta_ref);
    return u_ref * std::exp(s * x + c * x * x);
  }

  double
  local_slope(const double theta0)
  {
    return s + 2 * c * std::log(theta0 / theta_ref);
  }

  /// theta0 of indentation @p u0 (the root of the quadratic).
  double
  theta_of(const double u0)
  {
    const double y = std::log(u0 / u_ref);
    return theta_ref * std::exp((-s + std::sqrt(s * s + 4 * c * y)) / (2 * c));
  }

  /// A nip solver whose nips lie on the closed-form curve.
  class ClosedFormNip : public NipSolver
  {
  public:
    explicit ClosedFormNip(const Parameters::AllParameters &p)
        : description(describe_scene(p))
    {}

    ContactResult
    solve(const double theta0) override
    {
      ContactResult r;
      r.converged   = true;
      r.theta0      = theta0;
      r.indentation = indentation(theta0);
      r.nip_load    = 10 * r.indentation;
      return r;
    }

    double
    max_nip_angle() override
    {
      return 0.25 * numbers::PI;
    }

    MPI_Comm
    communicator() const override
    {
      return MPI_COMM_WORLD;
    }

    const SceneDescription &
    scene() const override
    {
      return description;
    }

  private:
    const SceneDescription description;
  };

  /// The solves per target of the sweep, each started 1e-4 off in u0,
  /// with the exact slope there if @p with_slope; the worst miss in
  /// @p worst.
  std::vector<unsigned int>
  sweep(const Parameters::AllParameters &p,
        const bool                       with_slope,
        double                          &worst)
  {
    ClosedFormNip             nip(p);
    NipControl                control(nip, p);
    std::vector<unsigned int> solves;
    worst = 0;
    for (const double target : {0.5, 1., 2., 3.})
      {
        const double        guess  = theta_of(target * (1 + 2e-4));
        const unsigned int  before = control.n_contact_solves();
        const ContactResult r =
          control.solve(target, guess, with_slope ? local_slope(guess) : 0.);
        solves.push_back(control.n_contact_solves() - before);
        worst =
          std::max(worst,
                   r.converged ? std::abs(r.indentation / target - 1) : 1.);
      }
    return solves;
  }

  std::string
  solve_counts(const std::vector<unsigned int> &v)
  {
    std::string out;
    for (const unsigned int n : v)
      out += (out.empty() ? "" : ", ") + std::to_string(n);
    return out;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  const auto                       p = testing::parameters_from_string(
    "subsection Contact\n set Mode = indentation\n set Values = 1\n"
                          " set Control tolerance = 1e-6\nend\n");

  double     worst  = 0;
  const auto hinted = sweep(p, true, worst);
  checker.check(worst < 1e-6,
                "with the slope: every answer within " + testing::num(worst) +
                  " < 1e-6 of its target");
  bool two_each = true;
  for (unsigned int i = 0; i < hinted.size(); ++i)
    two_each = two_each && hinted[i] == 2;
  checker.check(two_each,
                "with the slope: 2 solves per target (" + solve_counts(hinted) +
                  ")");

  const auto plain = sweep(p, false, worst);
  checker.check(worst < 1e-6 && plain[1] >= 3,
                "without it: within " + testing::num(worst) +
                  ", the second target takes 3 solves or more (" +
                  solve_counts(plain) + ")");
  return checker.result();
}
