#include <deal.II/base/exceptions.h>

#include <rollnip/face/foundation_law.h>
#include <rollnip/global.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rollnip
{
  namespace Face
  {
    double
    FoundationLaw::half_width(const double) const
    {
      return 0;
    }

    double
    FoundationLaw::peak_pressure(const double) const
    {
      return 0;
    }

    double
    FoundationLaw::largest_approach() const
    {
      return std::numeric_limits<double>::infinity();
    }

    LinearFoundation::LinearFoundation(const double k)
        : k(k)
    {}

    double
    LinearFoundation::load(const double delta) const
    {
      return delta > 0 ? k * delta : 0.;
    }

    double
    LinearFoundation::tangent(const double delta) const
    {
      return delta > 0 ? k : 0.;
    }

    LogLogPchip::LogLogPchip(const std::vector<double> &x,
                             const std::vector<double> &y)
    {
      AssertThrow(x.size() >= 2 && x.size() == y.size(),
                  ExcMessage("a sampled law needs two samples or more"));
      for (unsigned int i = 0; i < x.size(); ++i)
        {
          AssertThrow(x[i] > 0 && y[i] > 0 && (i == 0 || x[i] > x[i - 1]),
                      ExcMessage("a sampled law needs positive values at "
                                 "increasing positive approaches"));
          lx.push_back(std::log(x[i]));
          ly.push_back(std::log(y[i]));
        }
      const unsigned int  n = lx.size();
      std::vector<double> h(n - 1), delta(n - 1);
      for (unsigned int i = 0; i + 1 < n; ++i)
        {
          h[i]     = lx[i + 1] - lx[i];
          delta[i] = (ly[i + 1] - ly[i]) / h[i];
        }
      // Fritsch-Carlson: a weighted harmonic mean of the neighbouring
      // secants, zero where they differ in sign, keeps the cubic monotone.
      slope.assign(n, 0.);
      slope[0]     = delta[0];
      slope[n - 1] = delta[n - 2];
      for (unsigned int i = 1; i + 1 < n; ++i)
        if (delta[i - 1] * delta[i] > 0)
          {
            const double w1 = 2 * h[i] + h[i - 1], w2 = h[i] + 2 * h[i - 1];
            slope[i] = (w1 + w2) / (w1 / delta[i - 1] + w2 / delta[i]);
          }
    }

    void
    LogLogPchip::evaluate(const double t, double &v, double &d) const
    {
      const unsigned int n = lx.size();
      if (t <= lx[0])
        {
          d = (ly[1] - ly[0]) / (lx[1] - lx[0]);
          v = ly[0] + d * (t - lx[0]);
          return;
        }
      if (t >= lx[n - 1])
        {
          d = (ly[n - 1] - ly[n - 2]) / (lx[n - 1] - lx[n - 2]);
          v = ly[n - 1] + d * (t - lx[n - 1]);
          return;
        }
      const unsigned int i =
        std::upper_bound(lx.begin(), lx.end(), t) - lx.begin() - 1;
      const double h = lx[i + 1] - lx[i], s = (t - lx[i]) / h;
      const double s2 = s * s, s3 = s2 * s;
      v = (2 * s3 - 3 * s2 + 1) * ly[i] + (s3 - 2 * s2 + s) * h * slope[i] +
          (-2 * s3 + 3 * s2) * ly[i + 1] + (s3 - s2) * h * slope[i + 1];
      d = (6 * s2 - 6 * s) / h * ly[i] + (3 * s2 - 4 * s + 1) * slope[i] +
          (-6 * s2 + 6 * s) / h * ly[i + 1] + (3 * s2 - 2 * s) * slope[i + 1];
    }

    double
    LogLogPchip::value(const double x) const
    {
      if (x <= 0)
        return 0;
      double v, d;
      evaluate(std::log(x), v, d);
      return std::exp(v);
    }

    double
    LogLogPchip::derivative(const double x) const
    {
      if (x <= 0)
        return 0;
      double v, d;
      evaluate(std::log(x), v, d);
      return std::exp(v) * d / x;
    }

    SampledLaw::SampledLaw(const std::vector<double> &approach,
                           const std::vector<double> &line_load,
                           const std::vector<double> &half_width,
                           const std::vector<double> &peak_pressure)
        : p(approach, line_load)
        , b(approach, half_width)
        , peak(approach, peak_pressure)
    {}

    double
    SampledLaw::load(const double delta) const
    {
      return p.value(delta);
    }

    double
    SampledLaw::tangent(const double delta) const
    {
      return p.derivative(delta);
    }

    double
    SampledLaw::half_width(const double delta) const
    {
      return b.value(delta);
    }

    double
    SampledLaw::peak_pressure(const double delta) const
    {
      return peak.value(delta);
    }

    double
    SampledLaw::largest_approach() const
    {
      return p.last_abscissa();
    }
  } // namespace Face
} // namespace rollnip
