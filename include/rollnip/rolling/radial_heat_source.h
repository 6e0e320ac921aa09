#ifndef rollnip_rolling_radial_heat_source_h
#define rollnip_rolling_radial_heat_source_h

#include <rollnip/rolling/first_order_loss.h>

#include <functional>
#include <vector>

namespace rollnip
{
  /// The mean dissipation density of the @p circles (by increasing radius,
  /// degree + 1 of them per ring of cells, at the ring's radial Gauss
  /// points) as a function of the radius r [mm] -> [W/m^3]: in each ring
  /// the polynomial through its circles (exact in the ring's radial Gauss
  /// rule), zero outside the cover. The heat source of the temperature
  /// solve (CoverTemperature) for the first-order and the full route.
  std::function<double(double)>
  radial_heat_source(const std::vector<CircleLoss> &circles,
                     const unsigned int             degree);
} // namespace rollnip

#endif
