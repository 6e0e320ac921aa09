#include <rollnip/postprocess/error_estimate.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace rollnip
{
  namespace NipQuantity
  {
    namespace
    {
      struct Names
      {
        const char *key, *unit, *label;
      };

      const Names &
      names(const Index q)
      {
        static const Names table[n_quantities] = {
          {"theta0", "deg", "theta0"},
          {"P", "N_per_mm", "P"},
          {"u0", "mm", "u0"},
          {"half_chord", "mm", "b"},
          {"peak_pressure", "MPa", "peak p"},
          {"mean_pressure", "MPa", "mean p"},
          {"bond_sigma_rr_min", "MPa", "bond sigma_rr"},
          {"bond_sigma_rtheta_max", "MPa", "bond sigma_rtheta"}};
        return table[q];
      }
    } // namespace

    std::string
    key(const Index q)
    {
      return names(q).key;
    }

    std::string
    unit(const Index q)
    {
      return names(q).unit;
    }

    std::string
    label(const Index q)
    {
      return names(q).label;
    }
  } // namespace NipQuantity

  double
  error_order(const Parameters::Element /*element: the same orders*/,
              const NipQuantity::Index      q,
              const Parameters::ContactMode mode)
  {
    using namespace NipQuantity;
    switch (q)
      {
        // The contact edge: b, and theta0, which it follows, converge at
        // orders from 0.85 to 2 with either element, depending on the
        // scene (the pressure's square-root edge within one surface cell);
        // 1.2 keeps the estimate within a factor 0.6 to 2.3 of the error
        // over that range. (The mean pressure P / 2b takes the errors of P
        // and b: estimate_errors().)
        case theta0:
        case half_chord:
          return mode == Parameters::ContactMode::nip_angle ? 1 : 1.2;
        // P, u0 and the peak pressure: second order (Q2-P1 at least) at a
        // prescribed P or u0, where the errors of the edge and of the
        // load partly cancel; first order at a prescribed theta0, where
        // they follow the contact edge (the default run's sequence at
        // 8 deg: differences 0.031, 0.017, 0.0078, 0.0040 N/mm). The bond
        // traction from the core's nodal reactions follows the load: second
        // order at a prescribed P (doc/accuracy.md, "Bond and interface
        // tractions": Q1-P0 2.0 to 2.5 on a nip, 1.7 to 2.0 node by node
        // under a prescribed pressure), first at a prescribed theta0.
        default:
          return mode == Parameters::ContactMode::nip_angle ? 1 : 2;
      }
  }

  double
  ErrorEstimate::relative(const NipQuantity::Index q, const double value) const
  {
    if (!available || value == 0)
      return std::numeric_limits<double>::quiet_NaN();
    return error[q] / std::abs(value);
  }

  std::string
  ErrorEstimate::method(const Parameters::Element     element,
                        const Parameters::ContactMode mode,
                        const unsigned int            level) const
  {
    std::ostringstream s;
    s << "the same nip at mesh level " << companion_level << " beside level "
      << level << ", Richardson with the "
      << (element == Parameters::Element::q1_p0 ? "Q1-P0" : "Q2-P1")
      << " orders " << error_order(element, NipQuantity::load, mode)
      << " (P, u0, peak pressure), "
      << error_order(element, NipQuantity::half_chord, mode)
      << " (b, theta0) and "
      << error_order(element, NipQuantity::bond_sigma_rr, mode)
      << " (bond stresses); the mean pressure from P and b";
    return s.str();
  }

  ErrorEstimate
  estimate_errors(const NipNumbers             &answer,
                  const NipNumbers             &companion,
                  const Parameters::Element     element,
                  const Parameters::ContactMode mode,
                  const unsigned int            level,
                  const unsigned int            companion_level)
  {
    ErrorEstimate e;
    e.available       = true;
    e.companion_level = companion_level;
    for (unsigned int q = 0; q < NipQuantity::n_quantities; ++q)
      {
        const double f =
          std::pow(2., error_order(element, NipQuantity::Index(q), mode));
        const double d = std::abs(answer[q] - companion[q]);
        // The companion coarser: the answer's error is 1/(f - 1) of the
        // difference; finer: the answer is the coarser one, f/(f - 1).
        e.error[q] = companion_level < level ? d / (f - 1) : d * f / (f - 1);
      }
    // The mean pressure P / 2b is derived: its relative error is at most
    // the sum of those of P and b.
    using namespace NipQuantity;
    e.error[mean_pressure] =
      std::abs(answer[mean_pressure]) *
      (e.error[load] / std::abs(answer[load]) +
       e.error[half_chord] / std::abs(answer[half_chord]));
    return e;
  }

  double
  extrapolated_order(const Parameters::Element element)
  {
    return element == Parameters::Element::q1_p0 ? 1.5 : 2;
  }

  ExtrapolatedNumbers
  extrapolate_first_order(const NipNumbers         &fine,
                          const NipNumbers         &middle,
                          const NipNumbers         &coarse,
                          const Parameters::Element element)
  {
    const double        f = std::pow(2., extrapolated_order(element));
    ExtrapolatedNumbers x;
    for (unsigned int q = 0; q < NipQuantity::n_quantities; ++q)
      {
        x.value[q]          = 2 * fine[q] - middle[q];
        const double before = 2 * middle[q] - coarse[q];
        x.error[q]          = std::abs(x.value[q] - before) / (f - 1);
      }
    return x;
  }
} // namespace rollnip
