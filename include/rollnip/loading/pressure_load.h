#ifndef rollnip_loading_pressure_load_h
#define rollnip_loading_pressure_load_h

#include <deal.II/base/function_parser.h>

#include <rollnip/parameters.h>

#include <memory>

namespace rollnip
{
  /**
   * The follower pressure f(Theta) [MPa] of Load/Pressure function, a
   * function of the REFERENCE angle Theta of a surface point (doc/intro.md,
   * section 4). The expression is parsed once, when the object is made; a
   * parse error becomes a one-line message naming the parameter.
   */
  class PressureLoad
  {
  public:
    PressureLoad(const Parameters::Load     &load,
                 const Parameters::Geometry &geometry);

    /// f at the reference angle theta [rad] (full load, before scaling).
    double
    value(const double theta) const;

  private:
    std::unique_ptr<FunctionParser<1>> function;
  };
} // namespace rollnip

#endif
