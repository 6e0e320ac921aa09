// The counter surfaces of the contact iteration (contact/counter_surface.h)
// against their geometry, on R0 = 60.7 mm at u0 = 1.2 mm:
//  - every point of outline() has a zero gap (1e-12 mm), for the rigid
//    circle (Rbar = 76.2 mm), the plane and a deformed roll;
//  - gap_gradient and gap_derivative_u0 against central differences of
//    gap (step 1e-5 mm: agreement to 1e-7) at points in and around the nip;
//  - a deformed roll whose nodes lie on a circle of radius 76.2 mm is that
//    circle (its surface radius, linear in the angle between nodes, is
//    constant): its gap equals the rigid circle's to 1e-12 mm;
//  - make_counter_surface() gives the circle for a finite radius and the
//    plane for infinity.

#include <rollnip/contact/counter_surface.h>

#include "test_tools.h"

using namespace rollnip;

namespace
{
  constexpr double R0 = 60.7, Rbar = 76.2, u0 = 1.2;

  /// The nodes of a circle of radius @p radius in the mating roll's frame,
  /// @p n segments over the quarter from its line of centres.
  std::vector<Point<dim>>
  circle_nodes(const double radius, const unsigned int n)
  {
    std::vector<Point<dim>> nodes;
    for (unsigned int i = 0; i <= n; ++i)
      {
        const double phi = 0.5 * numbers::PI * i / n;
        nodes.emplace_back(radius * std::cos(phi), radius * std::sin(phi));
      }
    return nodes;
  }

  /// Points near the nip where the derivatives are checked.
  std::vector<Point<dim>>
  probes()
  {
    return {Point<dim>(R0 - 1.0, 0.3),
            Point<dim>(R0 - 1.5, 4.0),
            Point<dim>(R0 - 2.5, 9.0),
            Point<dim>(R0 - 0.5, -6.0)};
  }

  void
  check_surface(testing::Checker     &checker,
                const CounterSurface &surface,
                const std::string    &name)
  {
    double on_surface = 0;
    for (const auto &x : surface.outline(u0, 12., 50))
      on_surface = std::max(on_surface, std::abs(surface.gap(x, u0)));
    checker.check(on_surface < 1e-12,
                  name + ": the outline lies on the surface (largest |gap| " +
                    testing::num(on_surface) + " mm)");
    constexpr double h     = 1e-5;
    double           worst = 0;
    for (const auto &x : probes())
      {
        const Tensor<1, dim> g = surface.gap_gradient(x, u0);
        for (unsigned int d = 0; d < dim; ++d)
          {
            Point<dim> plus = x, minus = x;
            plus[d] += h;
            minus[d] -= h;
            const double fd =
              (surface.gap(plus, u0) - surface.gap(minus, u0)) / (2 * h);
            worst = std::max(worst, std::abs(fd - g[d]));
          }
        const double fd_u0 =
          (surface.gap(x, u0 + h) - surface.gap(x, u0 - h)) / (2 * h);
        worst =
          std::max(worst, std::abs(fd_u0 - surface.gap_derivative_u0(x, u0)));
      }
    checker.check(worst < 1e-7,
                  name + ": gap derivatives against central differences (" +
                    testing::num(worst) + ")");
  }
} // namespace

int
main()
{
  testing::Checker checker;
  RigidCircle      circle(R0, Rbar);
  FlatPlane        plane(R0);
  DeformedRoll     roll(R0, Rbar);
  roll.set_shape(circle_nodes(Rbar, 720));
  check_surface(checker, circle, "rigid circle");
  check_surface(checker, plane, "plane");
  check_surface(checker, roll, "deformed roll");

  // A roll deformed into a circle is the circle: rho(phi), linear between
  // the nodes, is constant, so the gaps agree to round-off on any polygon.
  DeformedRoll coarse(R0, Rbar);
  coarse.set_shape(circle_nodes(Rbar, 18));
  double worst = 0;
  for (const auto &x : probes())
    worst = std::max(worst, std::abs(coarse.gap(x, u0) - circle.gap(x, u0)));
  checker.check(worst < 1e-12,
                "a roll deformed into a circle (18 nodes) is the circle: gaps "
                "within " +
                  testing::num(worst) + " mm");

  checker.check(!make_counter_surface(R0, Rbar)->is_flat() &&
                  make_counter_surface(R0, Rbar)->radius() == Rbar &&
                  make_counter_surface(R0,
                                       std::numeric_limits<double>::infinity())
                    ->is_flat(),
                "make_counter_surface: a circle for Rbar = 76.2 mm, the plane "
                "for inf");
  return checker.result();
}
