#ifndef rollnip_loading_pressure_load_h
#define rollnip_loading_pressure_load_h

#include <deal.II/base/function_parser.h>

#include <rollnip/parameters.h>

#include <memory>
#include <string>
#include <vector>

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

    /// Throws a one-line message naming Load/Pressure function and the
    /// angle if f is NaN or infinite anywhere on [0, sector angle]
    /// (sampled at 0.01 deg and at the ends).
    void
    check_finite() const;

    /// Whether f is non-zero somewhere beyond the sector, up to @p theta
    /// [rad] (at most 180 deg): that part of the load is not applied.
    bool
    loads_beyond(const double theta) const;

    /// Where f is non-zero on [0, sector angle] and its peak, as the start
    /// of a line for the screen: an expression written in degrees shows as
    /// a load on the whole arc (check_applied_load() adds the resultant).
    std::string
    describe() const;

    /// The angle [rad] of [0, sector angle] where f is non-zero (sampled
    /// at 0.01 deg).
    double
    loaded_angle() const;

  private:
    std::unique_ptr<FunctionParser<1>> function;
    const double                       sector_angle;
    /// The sample angles [rad] of check_finite() and describe().
    std::vector<double>
    samples() const;
  };
} // namespace rollnip

#endif
