#include <deal.II/base/numbers.h>

#include <rollnip/global.h>
#include <rollnip/rolling/periodic_relaxation.h>

#include <cmath>

namespace rollnip
{
  BranchHistory
  periodic_branch(const std::vector<double>      &theta,
                  const std::vector<PolarTensor> &S,
                  const double                    g,
                  const double                    tau,
                  const double                    Omega)
  {
    const unsigned int n = theta.size();
    BranchHistory      b;
    b.Q.assign(n, {{0, 0, 0}});
    b.H.assign(n, {{0, 0, 0}});
    b.c.assign(n, 0.);
    if (n == 0 || Omega * tau <= 0 || g == 0)
      return b;
    // Step k -> k + 1 (mod n): decay a and instantaneous share c, stored
    // at the sample it ends on.
    std::vector<double> a(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        const unsigned int next = (k + 1) % n;
        double             dt   = theta[next] - theta[k];
        if (next == 0)
          dt += 2. * numbers::PI;
        const double x = dt / (Omega * tau);
        a[next]        = std::exp(-x);
        b.c[next]      = x > 1e-12 ? -g * std::expm1(-x) / x : g;
      }
    // One turn from Q_0 = 0 gives Q_0 = A Q_0 + B, A = e^(-2 pi/(Omega tau)).
    PolarTensor Q{{0, 0, 0}};
    auto        step = [&](const unsigned int k, const PolarTensor &Qk) {
      const unsigned int next = (k + 1) % n;
      PolarTensor        out;
      for (unsigned int c = 0; c < 3; ++c)
        out[c] = a[next] * Qk[c] + b.c[next] * (S[next][c] - S[k][c]);
      return out;
    };
    for (unsigned int k = 0; k < n; ++k)
      Q = step(k, Q);
    const double A = std::exp(-2. * numbers::PI / (Omega * tau));
    for (unsigned int c = 0; c < 3; ++c)
      b.Q[0][c] = Q[c] / (1. - A);
    for (unsigned int k = 0; k + 1 < n; ++k)
      b.Q[k + 1] = step(k, b.Q[k]);
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int c = 0; c < 3; ++c)
        b.H[k][c] = b.Q[k][c] - b.c[k] * S[k][c];
    return b;
  }

  double
  contract(const PolarTensor &A, const PolarTensor &B)
  {
    return A[0] * B[0] + 2 * A[1] * B[1] + A[2] * B[2];
  }

  /// Over a step of x = dtheta / (Omega tau), with s in [0, 1] along it,
  /// Q(s) = e^(-x s) Q_k + g (1 - e^(-x s)) / x dS, whose mean is
  /// f1 Q_k + g f2 dS with f1 = (1 - e^-x) / x and f2 = (1 - f1) / x.
  double
  branch_work(const std::vector<double>      &theta,
              const std::vector<PolarTensor> &S,
              const std::vector<PolarTensor> &E,
              const BranchHistory            &branch,
              const double                    g,
              const double                    tau,
              const double                    Omega)
  {
    const unsigned int n = theta.size();
    if (n == 0 || Omega * tau <= 0 || g == 0)
      return 0.;
    double work = 0;
    for (unsigned int k = 0; k < n; ++k)
      {
        const unsigned int next = (k + 1) % n;
        double             dt   = theta[next] - theta[k];
        if (next == 0)
          dt += 2. * numbers::PI;
        const double x = dt / (Omega * tau);
        const double f1 =
          x > 1e-4 ? -std::expm1(-x) / x : 1 - x / 2 + x * x / 6;
        const double f2 = x > 1e-4 ? (1 - f1) / x : 0.5 - x / 6 + x * x / 24;
        PolarTensor  mean, dE;
        for (unsigned int c = 0; c < 3; ++c)
          {
            mean[c] = f1 * branch.Q[k][c] + g * f2 * (S[next][c] - S[k][c]);
            dE[c]   = E[next][c] - E[k][c];
          }
        work += contract(mean, dE);
      }
    return work;
  }
} // namespace rollnip
