#ifndef rollnip_contact_indenter_h
#define rollnip_contact_indenter_h

#include <deal.II/base/point.h>

#include <rollnip/global.h>

#include <cmath>
#include <limits>

namespace rollnip
{
  /**
   * The rigid indenter of doc/intro.md section 7: a circle of radius Rbar
   * whose centre is at (R0 + Rbar - u0, 0), or, for Rbar = infinity, the
   * plane x1 = R0 - u0 (two identical covered rolls pressed together).
   */
  class Indenter
  {
  public:
    Indenter(const double outer_radius, const double indenter_radius)
        : R0(outer_radius)
        , Rbar(indenter_radius)
    {}

    bool
    is_flat() const
    {
      return !std::isfinite(Rbar);
    }

    /// Signed distance of x from the indenter surface at indentation u0,
    /// positive outside the indenter.
    double
    gap(const Point<dim> &x, const double u0) const
    {
      if (is_flat())
        return (R0 - u0) - x[0];
      const Point<dim> centre(R0 + Rbar - u0, 0.);
      return x.distance(centre) - Rbar;
    }

    /// d gap / d x (the outward unit normal of the indenter seen from x).
    Tensor<1, dim>
    gap_gradient(const Point<dim> &x, const double u0) const
    {
      if (is_flat())
        return Tensor<1, dim>({-1., 0.});
      const Point<dim> centre(R0 + Rbar - u0, 0.);
      return (x - centre) / x.distance(centre);
    }

    /// d gap / d u0 at fixed x.
    double
    gap_derivative_u0(const Point<dim> &x, const double u0) const
    {
      // The centre moves by -d u0 in x1: d gap = n . (0 - d centre).
      return is_flat() ? -1. : gap_gradient(x, u0)[0];
    }

    double
    radius() const
    {
      return Rbar;
    }

  private:
    const double R0;
    const double Rbar;
  };
} // namespace rollnip

#endif
