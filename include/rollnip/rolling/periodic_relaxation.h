#ifndef rollnip_rolling_periodic_relaxation_h
#define rollnip_rolling_periodic_relaxation_h

#include <array>
#include <vector>

namespace rollnip
{
  /// Polar components (rr, rtheta, thetatheta) of a symmetric 2x2 tensor.
  using PolarTensor = std::array<double, 3>;

  /// One Maxwell branch's overstress along a closed circle, with what the
  /// next equilibrium solve needs at every sample k: Q_k = c_k S_k + H_k,
  /// c_k the branch's instantaneous share of the last step into k and H_k
  /// what the history before it left.
  struct BranchHistory
  {
    std::vector<PolarTensor> Q, H;
    std::vector<double>      c;
  };

  /**
   * The steady periodic solution of one Maxwell branch (modulus ratio
   * @p g, time @p tau [s]) on a closed circle travelled at @p Omega [1/s]
   * towards increasing theta: along the material's path
   *   Omega dQ/dtheta + Q / tau = g Omega dS/dtheta,
   * with S given at the samples @p theta [rad] (increasing, within one
   * turn) as @p S and linear in theta between them. Each step from k to
   * k + 1 is integrated exactly,
   *   Q_k+1 = e^-x Q_k + g (1 - e^-x) / x (S_k+1 - S_k),  x = dtheta/(Omega
   * tau), and the closing step from the last sample back to the first, 2 pi on,
   * makes the solution periodic. Omega = 0 or tau = 0: Q = 0.
   */
  BranchHistory
  periodic_branch(const std::vector<double>      &theta,
                  const std::vector<PolarTensor> &S,
                  const double                    g,
                  const double                    tau,
                  const double                    Omega);

  /// A : B of two polar tensors (the shear counted twice).
  double
  contract(const PolarTensor &A, const PolarTensor &B);

  /**
   * The work of the branch @p branch (periodic_branch() of the same
   * @p theta, @p S, @p g, @p tau, @p Omega) over one turn, the closed
   * integral of Q : dE, with E given at the samples as @p E and, like S,
   * linear in theta between them: exact for that interpolation, so that
   * it tends to the first-order route's g tau Omega int S' : E' dtheta
   * when Omega tau is small against the samples' spacing and to the
   * trapezoidal rule when it is large. [MPa]
   */
  double
  branch_work(const std::vector<double>      &theta,
              const std::vector<PolarTensor> &S,
              const std::vector<PolarTensor> &E,
              const BranchHistory            &branch,
              const double                    g,
              const double                    tau,
              const double                    Omega);
} // namespace rollnip

#endif
