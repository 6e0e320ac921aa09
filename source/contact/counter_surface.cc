#include <rollnip/contact/counter_surface.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rollnip
{
  bool
  CounterSurface::is_flat() const
  {
    return !std::isfinite(radius());
  }

  RigidCircle::RigidCircle(const double outer_radius, const double radius)
      : R0(outer_radius)
      , Rbar(radius)
  {}

  Point<dim>
  RigidCircle::centre(const double u0) const
  {
    return Point<dim>(R0 + Rbar - u0, 0.);
  }

  double
  RigidCircle::gap(const Point<dim> &x, const double u0) const
  {
    return x.distance(centre(u0)) - Rbar;
  }

  Tensor<1, dim>
  RigidCircle::gap_gradient(const Point<dim> &x, const double u0) const
  {
    return (x - centre(u0)) / x.distance(centre(u0));
  }

  double
  RigidCircle::gap_derivative_u0(const Point<dim> &x, const double u0) const
  {
    // The centre moves by -d u0 along x1: d gap = n . (0 - d centre).
    return gap_gradient(x, u0)[0];
  }

  std::vector<Point<dim>>
  RigidCircle::outline(const double       u0,
                       const double       half_width,
                       const unsigned int n) const
  {
    std::vector<Point<dim>> points;
    for (unsigned int i = 0; i <= n; ++i)
      {
        const double y = half_width * i / n;
        points.emplace_back(centre(u0)[0] -
                              std::sqrt(std::max(0., Rbar * Rbar - y * y)),
                            y);
      }
    return points;
  }

  FlatPlane::FlatPlane(const double outer_radius)
      : R0(outer_radius)
  {}

  double
  FlatPlane::gap(const Point<dim> &x, const double u0) const
  {
    return (R0 - u0) - x[0];
  }

  Tensor<1, dim>
  FlatPlane::gap_gradient(const Point<dim> &, const double) const
  {
    return Tensor<1, dim>({-1., 0.});
  }

  double
  FlatPlane::gap_derivative_u0(const Point<dim> &, const double) const
  {
    return -1.;
  }

  double
  FlatPlane::radius() const
  {
    return std::numeric_limits<double>::infinity();
  }

  std::vector<Point<dim>>
  FlatPlane::outline(const double       u0,
                     const double       half_width,
                     const unsigned int n) const
  {
    std::vector<Point<dim>> points;
    for (unsigned int i = 0; i <= n; ++i)
      points.emplace_back(R0 - u0, half_width * i / n);
    return points;
  }

  DeformedRoll::DeformedRoll(const double outer_radius, const double radius)
      : R0(outer_radius)
      , R_mate(radius)
      , phi{0.}
      , rho{radius}
  {}

  void
  DeformedRoll::set_shape(const std::vector<Point<dim>> &nodes)
  {
    std::vector<std::pair<double, double>> polar;
    for (const auto &y : nodes)
      polar.emplace_back(std::atan2(std::abs(y[1]), y[0]), y.norm());
    // Sorted by angle: a search needs it even where a node overtook its
    // neighbour.
    std::sort(polar.begin(), polar.end());
    phi.clear();
    rho.clear();
    for (const auto &p : polar)
      if (phi.empty() || p.first > phi.back())
        {
          phi.push_back(p.first);
          rho.push_back(p.second);
        }
  }

  std::pair<double, double>
  DeformedRoll::surface_radius(const double angle) const
  {
    if (phi.size() < 2 || angle >= phi.back())
      return {rho.back(), 0.};
    const std::size_t j =
      std::upper_bound(phi.begin(), phi.end(), angle) - phi.begin();
    const std::size_t i     = j == 0 ? 0 : j - 1;
    const double      slope = (rho[i + 1] - rho[i]) / (phi[i + 1] - phi[i]);
    return {rho[i] + slope * (angle - phi[i]), slope};
  }

  Point<dim>
  DeformedRoll::mate_point(const Point<dim> &x, const double u0) const
  {
    const double D = R0 - u0 + rho.front();
    return Point<dim>(D - x[0], -x[1]);
  }

  Tensor<1, dim>
  DeformedRoll::gap_gradient_y(const Point<dim> &y) const
  {
    const double r2 = y.norm_square(), r = std::sqrt(r2);
    const double s     = y[1] < 0 ? -1. : 1.;
    const double angle = std::atan2(std::abs(y[1]), y[0]);
    // d phi / d y for phi = atan2(|y2|, y1).
    Tensor<1, dim> dphi;
    dphi[0] = -std::abs(y[1]) / r2;
    dphi[1] = s * y[0] / r2;
    return y / r - surface_radius(angle).second * dphi;
  }

  double
  DeformedRoll::gap(const Point<dim> &x, const double u0) const
  {
    const Point<dim> y = mate_point(x, u0);
    return y.norm() - surface_radius(std::atan2(std::abs(y[1]), y[0])).first;
  }

  Tensor<1, dim>
  DeformedRoll::gap_gradient(const Point<dim> &x, const double u0) const
  {
    // y = (D - x1, -x2): d y / d x = -I.
    return -gap_gradient_y(mate_point(x, u0));
  }

  double
  DeformedRoll::gap_derivative_u0(const Point<dim> &x, const double u0) const
  {
    // d y1 / d u0 = d D / d u0 = -1.
    return -gap_gradient_y(mate_point(x, u0))[0];
  }

  std::vector<Point<dim>>
  DeformedRoll::outline(const double u0,
                        const double half_width,
                        const unsigned int) const
  {
    // y = (D - x1, -x2): the mirrored half x2 >= 0 of the nodes.
    const double            D = R0 - u0 + rho.front();
    std::vector<Point<dim>> points;
    for (std::size_t i = 0; i < phi.size(); ++i)
      if (rho[i] * std::sin(phi[i]) <= half_width)
        points.emplace_back(D - rho[i] * std::cos(phi[i]),
                            rho[i] * std::sin(phi[i]));
    return points;
  }

  std::unique_ptr<CounterSurface>
  make_counter_surface(const double outer_radius, const double radius)
  {
    if (std::isfinite(radius))
      return std::make_unique<RigidCircle>(outer_radius, radius);
    return std::make_unique<FlatPlane>(outer_radius);
  }

  std::unique_ptr<CounterSurface>
  make_counter_surface(const SceneDescription &scene)
  {
    AssertThrow(scene.covered_mate() == nullptr,
                ExcMessage("the counter surface of a covered mating roll is "
                           "its deformed surface, not a rigid one"));
    return make_counter_surface(scene.roll.outer_radius(),
                                scene.counter_radius());
  }
} // namespace rollnip
