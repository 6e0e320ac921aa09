#ifndef rollnip_rolling_cover_circles_h
#define rollnip_rolling_cover_circles_h

#include <deal.II/base/quadrature.h>

#include <deal.II/distributed/tria.h>

#include <rollnip/body/roll_body.h>
#include <rollnip/global.h>

#include <array>
#include <vector>

namespace rollnip
{
  /**
   * The material circles r = const of the cover's structured mesh (cells
   * in rings) and the strain history along them, for the steady-rolling
   * post-process (doc/rolling.md). In steady rolling a material point
   * travels along its circle, so the state it meets at time t is the
   * elastic nip's state at reference angle Theta - Omega t, in the polar
   * frame of the reference point (which turns with the material).
   */

  /// The state at one point of a circle: reference angle [rad], the
  /// strain E (Green-Lagrange; linear theory: sym grad u) and the
  /// isochoric second Piola-Kirchhoff stress S_iso of the long-term
  /// elastic law [MPa], in polar components (rr, rtheta, thetatheta) of
  /// the reference frame.
  struct CircleSample
  {
    double                theta;
    std::array<double, 3> E, S;
  };

  /// One circle: its radius [mm], its radial quadrature weight [mm^2 per
  /// rad] (so that the area integral of a field is the sum over circles of
  /// weight times the integral of the field over theta), its layer and
  /// its samples, by increasing angle in [0, sector angle].
  struct MaterialCircle
  {
    double                    radius;
    double                    weight;
    unsigned int              layer;
    std::vector<CircleSample> samples;
  };

  /// One cell of a ring: which axis of the unit cell runs along the circle
  /// and the radii of its inner and outer edge [mm].
  struct RingCell
  {
    bool   xi_circumferential; ///< unit x along the circle, y radial
    double inner_radius, outer_radius;
  };

  /// The ring geometry of @p cell (reference configuration); throws a
  /// one-line message if its vertices do not lie on two circles about the
  /// roll axis.
  RingCell
  ring_cell(const Triangulation<dim>::cell_iterator &cell);

  /**
   * The points of a cell where the circles are sampled, in the unit cell,
   * for @p degree (1: Q1, 2: Q2): along the circle the points where the
   * element's gradient is superconvergent (the centre for Q1, the two
   * Gauss points for Q2), across it the degree + 1 Gauss points, which are
   * the circles. Entry [0] is for a cell whose unit x runs along the
   * circle, [1] for one whose unit y does. Also gives the radial unit
   * coordinate and Gauss weight of each point.
   */
  struct CircleQuadrature
  {
    std::array<Quadrature<dim>, 2> points;
    std::vector<double>            radial_coordinate, radial_weight;
  };

  CircleQuadrature
  circle_quadrature(const unsigned int degree);

  /// The circles of @p body's converged state, on every process
  /// (collective). C1 and C2 of each layer are the long-term elastic law's.
  std::vector<MaterialCircle>
  cover_circles(const RollBody &body);

  /// S_iso [MPa] in-plane (xx, xy, yy) of the Mooney-Rivlin law (C1, C2)
  /// at the deformation gradient @p F (plane strain, 3x3 C with C33 = 1):
  /// S_iso = J^(-2/3) DEV(2 C1 I + 2 C2 (I1bar I - Cbar)), with Cbar =
  /// J^(-2/3) C and DEV(A) = A - (A : C) C^-1 / 3; in linear theory
  /// 2 G dev(eps), G = 2 (C1 + C2).
  Tensor<2, dim>
  isochoric_stress(const Tensor<2, dim> &grad_u,
                   const double          C1,
                   const double          C2,
                   const bool            linear);
} // namespace rollnip

#endif
