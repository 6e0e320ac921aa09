#ifndef rollnip_face_foundation_law_h
#define rollnip_face_foundation_law_h

#include <cmath>
#include <vector>

/**
 * The foundation of the face model: the line load q [N/mm] the nip
 * carries at a local approach delta [mm] (doc/face.md). The nip is open,
 * q = 0, where delta <= 0.
 */
namespace rollnip
{
  namespace Face
  {
    class FoundationLaw
    {
    public:
      virtual ~FoundationLaw() = default;
      /// q(delta) [N/mm].
      virtual double
      load(const double delta) const = 0;
      /// dq/ddelta [N/mm^2].
      virtual double
      tangent(const double delta) const = 0;
      /// The nip's half-width b(delta) [mm]; 0 if the law does not know.
      virtual double
      half_width(const double delta) const;
      /// The nip's peak pressure [MPa]; 0 if the law does not know.
      virtual double
      peak_pressure(const double delta) const;
      /// The largest approach the law holds for [mm] (infinity: all).
      virtual double
      largest_approach() const;
    };

    /// q = k delta for delta > 0: Winkler's foundation.
    class LinearFoundation : public FoundationLaw
    {
    public:
      explicit LinearFoundation(const double k);
      double
      load(const double delta) const override;
      double
      tangent(const double delta) const override;

    private:
      double k;
    };

    /**
     * A positive increasing function sampled at increasing positive
     * abscissae, interpolated by the monotone piecewise cubic Hermite
     * interpolant (Fritsch and Carlson 1980) in log-log, so that power
     * laws are exact, and continued below the first sample by the power
     * law of the first interval (to 0 at 0) and above the last by that of
     * the last interval.
     */
    class LogLogPchip
    {
    public:
      LogLogPchip() = default;
      LogLogPchip(const std::vector<double> &x, const std::vector<double> &y);
      double
      value(const double x) const;
      double
      derivative(const double x) const;
      double
      last_abscissa() const
      {
        return lx.empty() ? 0 : std::exp(lx.back());
      }

    private:
      std::vector<double> lx, ly, slope;
      /// log value and d(log y)/d(log x) at log x = @p t.
      void
      evaluate(const double t, double &v, double &d) const;
    };

    /// The cross-section's nip law sampled by a sweep of approaches u0:
    /// P_2D(u0), b(u0) and the peak pressure, each a LogLogPchip.
    class SampledLaw : public FoundationLaw
    {
    public:
      SampledLaw(const std::vector<double> &approach,
                 const std::vector<double> &line_load,
                 const std::vector<double> &half_width,
                 const std::vector<double> &peak_pressure);
      double
      load(const double delta) const override;
      double
      tangent(const double delta) const override;
      double
      half_width(const double delta) const override;
      double
      peak_pressure(const double delta) const override;
      double
      largest_approach() const override;

    private:
      LogLogPchip p, b, peak;
    };
  } // namespace Face
} // namespace rollnip

#endif
