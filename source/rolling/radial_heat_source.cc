#include <deal.II/base/quadrature_lib.h>

#include <rollnip/rolling/radial_heat_source.h>

namespace rollnip
{
  namespace
  {
    /// One ring of cells: its radii [mm] and its circles' (r, D) pairs.
    struct Ring
    {
      double              inner, outer;
      std::vector<double> r, D;

      /// The polynomial through the circles at @p x.
      double
      operator()(const double x) const
      {
        double value = 0;
        for (unsigned int i = 0; i < r.size(); ++i)
          {
            double l = 1;
            for (unsigned int j = 0; j < r.size(); ++j)
              if (j != i)
                l *= (x - r[j]) / (r[i] - r[j]);
            value += l * D[i];
          }
        return value;
      }
    };
  } // namespace

  std::function<double(double)>
  radial_heat_source(const std::vector<CircleLoss> &circles,
                     const unsigned int             degree)
  {
    const unsigned int n = degree + 1;
    const QGauss<1>    gauss(n);
    std::vector<Ring>  rings;
    for (std::size_t c = 0; c + n <= circles.size(); c += n)
      {
        Ring ring;
        for (unsigned int q = 0; q < n; ++q)
          {
            ring.r.push_back(circles[c + q].radius);
            ring.D.push_back(circles[c + q].mean);
          }
        // The circles are the ring's Gauss points: its edges follow.
        const double xi0 = gauss.point(0)[0], xi1 = gauss.point(n - 1)[0];
        const double dr = (ring.r.back() - ring.r.front()) / (xi1 - xi0);
        ring.inner      = ring.r.front() - xi0 * dr;
        ring.outer      = ring.inner + dr;
        rings.push_back(ring);
      }
    return [rings](const double r) {
      for (const auto &ring : rings)
        if (r <= ring.outer * (1 + 1e-12))
          return r >= ring.inner * (1 - 1e-12) ? ring(r) : 0.;
      return 0.;
    };
  }
} // namespace rollnip
