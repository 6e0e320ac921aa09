#ifndef rollnip_contact_counter_surface_h
#define rollnip_contact_counter_surface_h

#include <deal.II/base/point.h>

#include <rollnip/global.h>
#include <rollnip/scene/scene_description.h>

#include <memory>
#include <utility>
#include <vector>

namespace rollnip
{
  /**
   * What the contact iteration needs of the body the cover is pressed
   * against: a signed gap and its derivatives, as functions of a point x of
   * the deformed cover and of the approach u0 of the two bodies along the
   * line of centres (the X1 axis). A new counter surface implements these
   * three functions, its effective radius and its outline for the output,
   * and make_counter_surface() picks it; nothing else changes.
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

    /// @p n + 1 points of the surface at approach @p u0 for x2 from 0 to
    /// @p half_width, in the roll's frame (the deformed configuration):
    /// what the output draws beside the cover.
    virtual std::vector<Point<dim>>
    outline(const double       u0,
            const double       half_width,
            const unsigned int n) const = 0;

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
    std::vector<Point<dim>>
    outline(const double       u0,
            const double       half_width,
            const unsigned int n) const override;

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
    std::vector<Point<dim>>
    outline(const double       u0,
            const double       half_width,
            const unsigned int n) const override;

  private:
    const double R0;
  };

  /**
   * The deformed outer surface of a second roll, seen from the first. The
   * second roll's frame has its centre at the origin and its line of
   * centres along +y1 towards the first roll; the first roll's point x is
   * y = (D - x1, -x2) there, with the distance of the centres
   * D = R0 - u0 + rho(0) chosen so that the two surfaces touch on the line
   * of centres at the first roll's indentation u0. The surface is the
   * polygon of the second roll's deformed surface nodes, as rho(phi) in
   * polar coordinates, linear between nodes and mirrored about the line
   * of centres; the gap is the radial distance |y| - rho(phi).
   */
  class DeformedRoll : public CounterSurface
  {
  public:
    /// @p outer_radius: R0 of the roll the surface is seen from;
    /// @p radius: the undeformed outer radius of the second roll.
    DeformedRoll(const double outer_radius, const double radius);

    /// The second roll's deformed surface nodes in its frame, from its
    /// line of centres on (the first on it).
    void
    set_shape(const std::vector<Point<dim>> &nodes);

    double
    gap(const Point<dim> &x, const double u0) const override;
    Tensor<1, dim>
    gap_gradient(const Point<dim> &x, const double u0) const override;
    double
    gap_derivative_u0(const Point<dim> &x, const double u0) const override;
    double
    radius() const override
    {
      return R_mate;
    }
    /// The polygon's own nodes with |y2| <= @p half_width (@p n unused).
    std::vector<Point<dim>>
    outline(const double       u0,
            const double       half_width,
            const unsigned int n) const override;

  private:
    /// x in the second roll's frame.
    Point<dim>
    mate_point(const Point<dim> &x, const double u0) const;

    /// d gap / d y in the second roll's frame.
    Tensor<1, dim>
    gap_gradient_y(const Point<dim> &y) const;

    /// rho(phi) and d rho / d phi, for phi >= 0.
    std::pair<double, double>
    surface_radius(const double phi) const;

    const double        R0;
    const double        R_mate;
    std::vector<double> phi, rho;
  };

  /// The circle of radius @p radius, or the plane for radius = infinity.
  std::unique_ptr<CounterSurface>
  make_counter_surface(const double outer_radius, const double radius);

  /// The rigid counter surface (circle or plane) of @p scene; throws for
  /// a covered mating roll, whose surface is its solver's (DeformedRoll).
  std::unique_ptr<CounterSurface>
  make_counter_surface(const SceneDescription &scene);
} // namespace rollnip

#endif
