#include <deal.II/base/function_parser.h>

#include <rollnip/loading/pressure_load.h>

#include <iostream>
#include <map>

namespace rollnip
{
  PressureLoad::PressureLoad(const Parameters::Load     &load,
                             const Parameters::Geometry &geometry)
      : function(std::make_unique<FunctionParser<1>>(1))
  {
    const std::map<std::string, double> constants = {
      {"p0", load.p0},
      {"theta0", load.theta0},
      {"R0", geometry.outer_radius},
      {"R1", geometry.inner_radius},
      {"pi", numbers::PI}};
    // muparser's diagnostics go to std::cerr; the message below replaces
    // them with one line.
    struct SilenceCerr
    {
      std::streambuf *saved = std::cerr.rdbuf(nullptr);
      ~SilenceCerr()
      {
        std::cerr.rdbuf(saved);
      }
    } silence;
    try
      {
        function->initialize("theta", load.pressure_function, constants);
        // muparser reports some errors (unknown variables) only on use.
        const double f = function->value(Point<1>(0.));
        (void)f;
      }
    catch (...)
      {
        AssertThrow(false,
                    ExcMessage("Load/Pressure function: cannot parse '" +
                               load.pressure_function +
                               "' (a muparser expression in theta, with "
                               "constants p0, theta0, R0, R1, pi)"));
      }
  }

  double
  PressureLoad::value(const double theta) const
  {
    return function->value(Point<1>(theta));
  }
} // namespace rollnip
