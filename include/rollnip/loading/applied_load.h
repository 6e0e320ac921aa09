#ifndef rollnip_loading_applied_load_h
#define rollnip_loading_applied_load_h

#include <rollnip/body/roll_body.h>

#include <string>

namespace rollnip
{
  /**
   * The pressure of Load/Pressure function as the discretisation applies
   * it (a pressure scene, before the solve): the resultant on the
   * undeformed loaded boundary from the quadrature of the assembly, not
   * from the expression, so that a zone the quadrature does not see shows
   * as no load. Throws a one-line message naming Load/theta0 (or
   * Load/Pressure function) when the zone where the pressure is non-zero
   * is narrower than two surface cells or missed by every quadrature
   * point, with the cell size it would need; otherwise returns the line
   * for the screen (collective).
   */
  std::string
  check_applied_load(const RollBody &body);
} // namespace rollnip

#endif
