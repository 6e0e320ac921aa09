#include <deal.II/base/function_parser.h>

#include <rollnip/loading/pressure_load.h>
#include <rollnip/output/silence_cerr.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace rollnip
{
  namespace
  {
    /// The first 60 characters of @p text, "..." if there is more.
    std::string
    first_line(const std::string &text)
    {
      constexpr std::size_t shown = 60;
      std::string           line  = text.substr(0, shown);
      std::replace(line.begin(), line.end(), '\n', ' ');
      return text.size() > shown ? line + "..." : line;
    }

    /// muparser's @p reason in one line, with its expression length limit
    /// spelled out for an expression of @p length characters.
    std::string
    one_line(std::string reason, const std::size_t length)
    {
      std::replace(reason.begin(), reason.end(), '\n', ' ');
      while (!reason.empty() &&
             std::isspace(static_cast<unsigned char>(reason.back())))
        reason.pop_back();
      const auto start = reason.find_first_not_of(' ');
      reason           = start == std::string::npos ? "" : reason.substr(start);
      if (length >= 20000)
        reason += " (muparser takes at most 20000 characters without "
                  "blanks; this one has " +
                  std::to_string(length) + ")";
      return reason.size() > 200 ? reason.substr(0, 200) + "..." : reason;
    }
  } // namespace

  PressureLoad::PressureLoad(const Parameters::Load     &load,
                             const Parameters::Geometry &geometry)
      : function(std::make_unique<FunctionParser<1>>(1))
      , sector_angle(geometry.sector_angle)
  {
    const std::map<std::string, double> constants = {
      {"p0", load.p0},
      {"theta0", load.theta0},
      {"R0", geometry.outer_radius},
      {"R1", geometry.inner_radius},
      {"pi", numbers::PI}};
    // muparser's diagnostics go to std::cerr; the message below replaces
    // them with one line.
    const SilenceCerr silence;
    // muparser ignores blanks but counts them against its limit of 20000
    // characters.
    std::string expression = load.pressure_function;
    expression.erase(std::remove_if(expression.begin(),
                                    expression.end(),
                                    [](const unsigned char c) {
                                      return std::isspace(c);
                                    }),
                     expression.end());
    std::string reason;
    try
      {
        function->initialize("theta", expression, constants);
        // muparser reports some errors (unknown variables) only on use.
        const double f = function->value(Point<1>(0.));
        (void)f;
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        reason = info.str();
      }
    catch (const std::exception &e)
      {
        reason = e.what();
      }
    catch (...)
      {
        reason = "unknown error";
      }
    AssertThrow(reason.empty(),
                ExcMessage("Load/Pressure function: cannot parse '" +
                           first_line(load.pressure_function) +
                           "' (a muparser expression in theta, with "
                           "constants p0, theta0, R0, R1, pi): " +
                           one_line(reason, expression.size())));
  }

  double
  PressureLoad::value(const double theta) const
  {
    return function->value(Point<1>(theta));
  }

  std::vector<double>
  PressureLoad::samples() const
  {
    // Midpoints of 0.01 deg intervals: the load is used at quadrature
    // points, never exactly at the ends (sin(x)/x at 0 is fine).
    const double        step = 0.01 * numbers::PI / 180;
    const unsigned int  n    = std::ceil(sector_angle / step);
    std::vector<double> theta(n);
    for (unsigned int i = 0; i < n; ++i)
      theta[i] = sector_angle * (i + 0.5) / n;
    return theta;
  }

  bool
  PressureLoad::loads_beyond(const double theta) const
  {
    const double end = std::min(theta, numbers::PI);
    for (unsigned int i = 1; i <= 100; ++i)
      {
        const double f = value(sector_angle + (end - sector_angle) * i / 100.);
        if (std::isfinite(f) && f != 0)
          return true;
      }
    return false;
  }

  void
  PressureLoad::check_finite() const
  {
    for (const double theta : samples())
      {
        const double f = value(theta);
        if (!std::isfinite(f))
          {
            std::ostringstream s;
            s << "Load/Pressure function is " << f
              << " at theta = " << theta * 180 / numbers::PI
              << " deg (theta is the reference angle in rad): the load must "
                 "be finite on the whole arc, including beyond the nip";
            AssertThrow(false, ExcMessage(s.str()));
          }
      }
  }

  double
  PressureLoad::loaded_angle() const
  {
    const std::vector<double> theta  = samples();
    unsigned int              loaded = 0;
    for (const double t : theta)
      loaded += value(t) != 0;
    return sector_angle * loaded / theta.size();
  }

  std::string
  PressureLoad::describe() const
  {
    const std::vector<double> theta = samples();
    double                    first = -1, last = -1, peak = 0, peak_at = 0;
    for (const double t : theta)
      {
        const double f = value(t);
        if (f != 0)
          {
            first = first < 0 ? t : first;
            last  = t;
          }
        if (std::abs(f) > std::abs(peak))
          {
            peak    = f;
            peak_at = t;
          }
      }
    const double       deg = 180 / numbers::PI;
    std::ostringstream s;
    s << std::setprecision(4);
    if (first < 0)
      s << "Load: the pressure is zero on the whole outer arc";
    else
      s << "Load: pressure non-zero for theta in [" << first * deg << ", "
        << last * deg << "] deg, peak " << peak << " MPa at " << peak_at * deg
        << " deg";
    return s.str();
  }
} // namespace rollnip
