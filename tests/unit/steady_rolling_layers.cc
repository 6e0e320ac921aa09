// The full steady rolling of a two-layer cover (doc/rolling.md, section 7)
// with different Prony terms per layer, against independent truth:
// - at zero speed the whole-circle nip under approach control is the
//   symmetric (half-model) contact solver's layered nip: the same P;
// - at small V tau / b the rolling resistance, from the dissipation and
//   from the contact moment, is the first-order route's (first_order_loss()
//   on the same mesh's elastic nip, which reads each circle's layer and
//   that layer's Prony terms itself), for the whole cover and for each
//   layer's branches alone; to first order the two layers' losses add.

#include <rollnip/rolling/steady_rolling.h>
#include <rollnip/rolling/steady_rolling_sweep.h>

#include "steady_rolling_scene.h"
#include "test_tools.h"

using namespace rollnip;

namespace
{
  constexpr double R0 = 60.7, R1 = 47.2, Rbar = 76.2; // mm
  /// Base layer (4.5 mm, a little stiffer, lossier) and top stock (9 mm),
  /// from the core.
  const Parameters::ViscousLayer base{{2.}, {2e-4}}, top{{1.}, {1e-4}};
  constexpr double               tau_max = 2e-4; // s

  struct Loss
  {
    double energy, moment, first_order, load;
  };

  /// The steady rolling at V tau_max / b = @p ratio of the cover with the
  /// branches @p layers (base, top) from the elastic nip at @p u0.
  Loss
  roll(const Parameters::Material                  &material,
       const std::vector<Parameters::ViscousLayer> &layers,
       const double                                 u0,
       const double                                 theta0,
       const double                                 ratio,
       testing::Checker                            &checker)
  {
    SteadyRollingScene s;
    s.material               = material;
    s.viscous                = layers;
    s.indenter_radius        = Rbar;
    s.layout.layer_radii     = {R1, R1 + 4.5, R0};
    s.layout.fine_half_angle = 2.5 * theta0;
    s.layout.fine_cells      = 100;
    s.layout.radial_cells    = 16;
    s.layout.radial_grading  = 0.3;
    SteadyRolling rolling(s);
    checker.check(rolling.solve_elastic(u0, 2), "elastic nip converged");
    const auto          still   = rolling.result();
    const auto          circles = rolling.circles();
    const double        V = ratio * still.half_width / tau_max * 1e-3; // m/s
    Parameters::Rolling prony;
    prony.layers = layers;
    checker.check(rolling.solve_speed(V),
                  "converged at V tau / b = " + testing::num(ratio));
    const auto r = rolling.result();
    return {r.resistance_energy,
            r.resistance_moment,
            first_order_resistance(circles, prony, R0, V),
            still.load};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  const double                     theta0     = 3 * numbers::PI / 180;
  const auto                       parameters = testing::rolling_nip_parameters(
    3,
    "subsection Material\n set Layer order = core first\n set C1 = 0.3, "
                          "0.25\n set C2 = 0.06, 0.05\n set Layer thicknesses = 4.5, 9\nend\n");
  const ContactResult nip = testing::symmetric_nip(parameters, theta0);
  checker.check(nip.converged, "symmetric layered nip converged");

  const Parameters::ViscousLayer none{{0.}, {1e-4}};
  const double                   ratio = 0.003;
  const Loss                     both  = roll(
    parameters.material, {base, top}, nip.indentation, theta0, ratio, checker);
  const Loss base_only = roll(
    parameters.material, {base, none}, nip.indentation, theta0, ratio, checker);
  const Loss top_only = roll(
    parameters.material, {none, top}, nip.indentation, theta0, ratio, checker);
  std::cout << "  symmetric solver P = " << nip.nip_load
            << " N/mm, whole circle P = " << both.load << " N/mm" << std::endl;
  checker.check(std::abs(both.load / nip.nip_load - 1) < 0.005,
                "zero speed: P within 0.5 % of the symmetric solver's (" +
                  testing::num(both.load / nip.nip_load - 1) + ")");
  for (const auto &[name, loss] : {std::make_pair("both layers", both),
                                   std::make_pair("base layer", base_only),
                                   std::make_pair("top layer", top_only)})
    {
      std::cout << std::scientific << std::setprecision(5) << "  " << name
                << ": F_r energy " << loss.energy << ", moment " << loss.moment
                << ", first order " << loss.first_order << " N/mm" << std::endl;
      checker.check(std::abs(loss.energy / loss.first_order - 1) < 0.02,
                    std::string(name) + ": full F_r / first order - 1 = " +
                      testing::num(loss.energy / loss.first_order - 1) +
                      " (within 2 %)");
      // Measured 1.010 (both), 1.008 (top), 1.020 (base, whose loss is a
      // seventh of the whole: a smaller moment out of the same large
      // ones); steady_rolling.cc measures 1.010 at V tau / b = 0.003 on
      // one layer.
      const double balance = loss.energy > 0.5 * both.energy ? 0.02 : 0.03;
      checker.check(std::abs(loss.moment / loss.energy - 1) < balance,
                    std::string(name) + ": moment / dissipation = " +
                      testing::num(loss.moment / loss.energy) + " (within " +
                      testing::num(100 * balance) + " %)");
    }
  const double sum = base_only.energy + top_only.energy;
  checker.check(std::abs(both.energy / sum - 1) < 0.005 &&
                  base_only.energy > 0.1 * both.energy,
                "the layers' losses add: both / (base + top) - 1 = " +
                  testing::num(both.energy / sum - 1) +
                  " (within 0.5 %), base share " +
                  testing::num(base_only.energy / both.energy));
  return checker.result();
}
