#ifndef rollnip_geometry_angles_h
#define rollnip_geometry_angles_h

#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>

#include <rollnip/global.h>

#include <cmath>

namespace rollnip
{
  /// Degrees per radian, for the .prm and output files (which use degrees).
  constexpr double degrees_per_radian = 180. / numbers::PI;

  /**
   * The reference polar angle Theta of a point of the cover, in
   * [-pi/2, 3 pi/2). Sectors reach 180 deg, where atan2 returns -pi for a
   * round-off negative X2: every place that keys, loads or reports by
   * angle takes it from here, so that such a point is at +pi everywhere.
   */
  inline double
  reference_angle(const Point<dim> &X)
  {
    const double theta = std::atan2(X[1], X[0]);
    return theta < -0.5 * numbers::PI ? theta + 2 * numbers::PI : theta;
  }
} // namespace rollnip

#endif
