#ifndef rollnip_contact_counter_surface_h
#define rollnip_contact_counter_surface_h

#include <deal.II/base/point.h>

#include <rollnip/global.h>

#include <memory>

namespace rollnip
{
  /**
   * What the contact iteration needs of the body the cover is pressed
   * against: a signed gap and its derivatives, as functions of a point x of
   * the deformed cover and of the approach u0 of the two bodies along the
   * line of centres (the X1 axis). A new counter surface implements these
   * three functions and its effective radius; nothing else changes.
   */
  class CounterSurface
  {
  public:
    virtual ~CounterSurface() = default;

    /// Signed distance of x from the surface at approach u0 [mm],
    /// positive outside (no contact).
    virtual double
    gap(const Point<dim> &x, const double u0) const = 0;

    /// d gap / d x: the unit normal of the surface seen from x.
    virtual Tensor<1, dim>
    gap_gradient(const Point<dim> &x, const double u0) const = 0;

    /// d gap / d u0 at fixed x.
    virtual double
    gap_derivative_u0(const Point<dim> &x, const double u0) const = 0;

    /// The radius of curvature of the surface [mm] (infinity: flat).
    virtual double
    radius() const = 0;

    bool
    is_flat() const;
  };

  /**
   * The rigid circle of radius Rbar whose centre is at (R0 + Rbar - u0, 0)
   * (doc/intro.md, section 7).
   */
  class RigidCircle : public CounterSurface
  {
  public:
    RigidCircle(const double outer_radius, const double radius);

    double
    gap(const Point<dim> &x, const double u0) const override;
    Tensor<1, dim>
    gap_gradient(const Point<dim> &x, const double u0) const override;
    double
    gap_derivative_u0(const Point<dim> &x, const double u0) const override;
    double
    radius() const override
    {
      return Rbar;
    }

  private:
    Point<dim>
    centre(const double u0) const;

    const double R0;
    const double Rbar;
  };

  /**
   * The rigid plane x1 = R0 - u0: the limit Rbar = infinity, and by
   * symmetry the nip of two identical covered rolls.
   */
  class FlatPlane : public CounterSurface
  {
  public:
    explicit FlatPlane(const double outer_radius);

    double
    gap(const Point<dim> &x, const double u0) const override;
    Tensor<1, dim>
    gap_gradient(const Point<dim> &x, const double u0) const override;
    double
    gap_derivative_u0(const Point<dim> &x, const double u0) const override;
    double
    radius() const override;

  private:
    const double R0;
  };

  /// The circle of radius @p radius, or the plane for radius = infinity.
  std::unique_ptr<CounterSurface>
  make_counter_surface(const double outer_radius, const double radius);
} // namespace rollnip

#endif
