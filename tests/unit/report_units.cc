// The unit table of the reports (include/rollnip/output/units.h) against
// the definitions: 1 in = 25.4 mm and 1 lbf = 4.4482216152605 N exactly
// (the international inch and pound), so 1 psi = 6894.757293 Pa,
// 1 pli = 0.1751268352 N/mm and 1 ft/min = 0.3048 m/min; the SI units are
// the program's own (factor 1). Speeds are read with their unit in any
// case (1969 fpm = 600.1512 m/min, 10 m/s = 600 m/min), a bare number is
// m/min, and a wrong unit or a negative speed is refused naming
// Contact/Surface speed; Output/Units takes SI or US in any case.

#include <deal.II/base/exceptions.h>

#include <rollnip/output/units.h>

#include "test_tools.h"

#include <cmath>
#include <string>

using namespace rollnip;

namespace
{
  /// The message of what @p f throws, "" if nothing.
  template <typename F>
  std::string
  message_of(F f)
  {
    try
      {
        f();
      }
    catch (const std::exception &e)
      {
        return e.what();
      }
    return "";
  }

  bool
  close(const double a, const double b, const double tol = 1e-12)
  {
    return std::abs(a / b - 1) < tol;
  }
} // namespace

int
main()
{
  testing::Checker checker;
  using Units::Quantity;
  const auto us = Parameters::UnitSystem::us;
  const auto si = Parameters::UnitSystem::si;

  checker.check(close(Units::unit(Quantity::length, us)(25.4), 1.) &&
                  Units::unit(Quantity::length, us).column == "in",
                "25.4 mm = 1 in");
  checker.check(
    close(Units::unit(Quantity::pressure, us)(1.), 1e6 / 6894.757293168),
    "1 MPa = " + testing::num(Units::unit(Quantity::pressure, us)(1.)) +
      " psi (1 psi = 6894.757293 Pa)");
  checker.check(close(Units::unit(Quantity::line_load, us)(0.1751268352),
                      1.,
                      1e-9) &&
                  Units::unit(Quantity::line_load, us).name == "pli",
                "0.1751268352 N/mm = 1 pli");
  checker.check(close(Units::unit(Quantity::force, us)(4.4482216152605), 1.),
                "4.4482216152605 N = 1 lbf");
  checker.check(close(Units::unit(Quantity::speed, us)(0.3048), 1.) &&
                  Units::unit(Quantity::speed, us).name == "fpm",
                "0.3048 m/min = 1 fpm");
  bool si_identity = true;
  for (const auto q : {Quantity::length,
                       Quantity::pressure,
                       Quantity::line_load,
                       Quantity::force,
                       Quantity::speed,
                       Quantity::time})
    si_identity = si_identity && Units::unit(q, si)(1.2345) == 1.2345;
  checker.check(si_identity &&
                  Units::unit(Quantity::line_load, si).column == "N_per_mm" &&
                  Units::unit(Quantity::speed, si).column == "m_per_min" &&
                  Units::unit(Quantity::time, us).name == "ms",
                "SI is the program's units (factor 1, columns N_per_mm, "
                "m_per_min); times stay in ms");

  checker.check(close(Units::speed_in_m_per_min("1969 fpm"), 600.1512) &&
                  close(Units::speed_in_m_per_min("1969 FPM"), 600.1512) &&
                  close(Units::speed_in_m_per_min("10 m/s"), 600.) &&
                  close(Units::speed_in_m_per_min("600 M/min"), 600.) &&
                  close(Units::speed_in_m_per_min("600m/min"), 600.) &&
                  Units::speed_in_m_per_min("600") == 600. &&
                  Units::speed_in_m_per_min("0") == 0.,
                "speeds: 1969 fpm = " +
                  testing::num(Units::speed_in_m_per_min("1969 fpm")) +
                  " m/min, 10 m/s = 600 m/min, a bare number is m/min");
  bool refused = true;
  for (const char *bad : {"600 mph", "-5", "fast", "600 m/min extra", ""})
    refused = refused && message_of([bad] {
                           Units::speed_in_m_per_min(bad);
                         }).find("Contact/Surface speed") != std::string::npos;
  checker.check(refused,
                "600 mph, -5, fast, trailing words and an empty speed are "
                "refused naming Contact/Surface speed");
  checker.check(Units::system_from_string("us") == us &&
                  Units::system_from_string("Si") == si &&
                  message_of([] {
                    Units::system_from_string("imperial");
                  }).find("Output/Units") != std::string::npos,
                "Output/Units: SI or US in any case, anything else refused");
  return checker.result();
}
