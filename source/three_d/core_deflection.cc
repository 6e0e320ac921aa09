#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <rollnip/output/atomic_file.h>
#include <rollnip/output/silence_cerr.h>
#include <rollnip/three_d/core_deflection.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

namespace rollnip
{
  namespace three_d
  {
    using namespace dealii;

    namespace
    {
      /// muparser's message in one line of at most 160 characters.
      std::string
      one_line(std::string reason)
      {
        std::replace(reason.begin(), reason.end(), '\n', ' ');
        while (!reason.empty() &&
               std::isspace(static_cast<unsigned char>(reason.back())))
          reason.pop_back();
        const auto start = reason.find_first_not_of(' ');
        reason = start == std::string::npos ? "" : reason.substr(start);
        return reason.size() > 160 ? reason.substr(0, 160) + "..." : reason;
      }
    } // namespace

    CoreDeflection::CoreDeflection(const std::string &expression)
        : function(std::make_unique<FunctionParser<1>>(1))
    {
      std::string compact = expression;
      compact.erase(std::remove_if(compact.begin(),
                                   compact.end(),
                                   [](const unsigned char c) {
                                     return std::isspace(c);
                                   }),
                    compact.end());
      if (compact.empty())
        compact = "0";
      zero = compact == "0";
      std::string reason;
      {
        const SilenceCerr silence;
        try
          {
            function->initialize("z", compact, {{"pi", numbers::PI}});
            // muparser reports unknown variables only on use.
            (void)function->value(Point<1>(0.));
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
      }
      AssertThrow(reason.empty(),
                  ExcMessage("Three d/Core deflection: cannot parse '" +
                             expression.substr(0, 60) +
                             "' (a muparser expression in z [mm] with the "
                             "constant pi): " +
                             one_line(reason)));
    }

    double
    CoreDeflection::value(const double z) const
    {
      const double v = function->value(Point<1>(z));
      AssertThrow(std::isfinite(v),
                  ExcMessage("Three d/Core deflection is not finite at z = " +
                             std::to_string(z) + " mm"));
      return v;
    }

    std::vector<std::pair<double, double>>
    consistent_line_load(const std::vector<std::pair<double, double>> &lumped)
    {
      const std::size_t n = lumped.size();
      if (n < 2)
        return lumped;
      const double h = (lumped.back().first - lumped.front().first) / (n - 1);
      // The tridiagonal M = h/6 (1, 4, 1) with h/3 on the two end
      // diagonals; f_j = lumped q_j times the plane's share of the length.
      std::vector<double> diagonal(n, 2 * h / 3), rhs(n);
      diagonal.front() = diagonal.back() = h / 3;
      const double off                   = h / 6;
      for (std::size_t j = 0; j < n; ++j)
        rhs[j] = lumped[j].second * (j == 0 || j + 1 == n ? h / 2 : h);
      // Thomas algorithm.
      for (std::size_t j = 1; j < n; ++j)
        {
          const double m = off / diagonal[j - 1];
          diagonal[j] -= m * off;
          rhs[j] -= m * rhs[j - 1];
        }
      std::vector<std::pair<double, double>> q(lumped);
      q[n - 1].second = rhs[n - 1] / diagonal[n - 1];
      for (std::size_t j = n - 1; j-- > 0;)
        q[j].second = (rhs[j] - off * q[j + 1].second) / diagonal[j];
      return q;
    }

    void
    write_core_profile(const std::string                            &path,
                       const std::vector<std::pair<double, double>> &lumped,
                       const CoreDeflection                         &core,
                       const double                                  u0)
    {
      const auto q = consistent_line_load(lumped);
      write_atomically(path, [&](std::ostream &out) {
        out << std::setprecision(10)
            << "z_mm,core_deflection_v_mm,local_approach_mm,"
               "line_load_N_per_mm,line_load_lumped_N_per_mm\n";
        for (std::size_t j = 0; j < q.size(); ++j)
          {
            const double v = core.value(q[j].first);
            out << q[j].first << ',' << v << ',' << u0 - v << ',' << q[j].second
                << ',' << lumped[j].second << '\n';
          }
      });
    }
  } // namespace three_d
} // namespace rollnip
