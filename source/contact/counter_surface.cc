#include <rollnip/contact/counter_surface.h>

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

  std::unique_ptr<CounterSurface>
  make_counter_surface(const double outer_radius, const double radius)
  {
    if (std::isfinite(radius))
      return std::make_unique<RigidCircle>(outer_radius, radius);
    return std::make_unique<FlatPlane>(outer_radius);
  }
} // namespace rollnip
