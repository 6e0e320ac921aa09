#ifndef rollnip_contact_nip_control_h
#define rollnip_contact_nip_control_h

#include <rollnip/contact/inverse_contact.h>
#include <rollnip/parameters.h>

#include <string>
#include <vector>

namespace rollnip
{
  /**
   * Load and indentation control (Contact/Mode = load or indentation,
   * doc/intro.md section 7): finds the theta0 whose nip carries the target
   * P or has the target u0. On the nip-fitted mesh q(theta0) (q = P or u0)
   * is smooth and rising, close to a power law, so a secant iteration on
   * log q against log theta0 converges in a few contact solves:
   *  - it starts from the inverse quadratic (in log-log) through three
   *    converged nips of the sweep spread towards the target (the power
   *    law through two while there are fewer); for the first nip, from
   *    the theta0 and the slope of the same target solved on the scene at
   *    mesh level 0 (coarse_first_guess.h), or, on a level-0 scene, from
   *    a guess below the half-width of Hertz and of the thin layer (both
   *    softer than a bonded layer, so both too wide);
   *  - a contact solve that fails is stepped back from, halfway to the
   *    largest converged theta0 below it;
   *  - a target is refused as out of reach only when theta0 would pass the
   *    largest the mesh takes, or the contact solve keeps failing just
   *    above a converged nip (the cover cannot carry more); the message
   *    names the largest q reached. An iteration that stalls (on
   *    round-off, or within its Maximum iterations) or fails at every
   *    theta0 down to a thousandth of the first says so instead.
   * One object per sweep: every converged nip is remembered.
   */
  class NipControl
  {
  public:
    NipControl(NipSolver &contact, const Parameters::AllParameters &p);

    /// The nip for @p target: theta0 [rad] for Mode = nip angle, else P
    /// [N/mm] or u0 [mm]; the first theta0 tried is @p guess [rad] if
    /// positive (the same nip on another mesh), else a prediction; the
    /// secant from it takes the slope @p guess_slope (d log q / d log
    /// theta0 of that other mesh) if positive.
    ContactResult
    solve(const double target,
          const double guess       = 0,
          const double guess_slope = 0);

    /// Whether solves at a theta0 far from the target may stop early
    /// (on by default). A provisional solve's q depends on the state it
    /// started from, and so, within Contact/Control tolerance, does the
    /// answer; a control whose starting states differ with the number of
    /// processes (the error estimate's companion) turns it off.
    void
    allow_provisional(const bool allow)
    {
      provisional_allowed = allow;
    }

    /// Contact solves (inverse iterations) run so far, failed ones too.
    unsigned int
    n_contact_solves() const
    {
      return n_solves;
    }

    /// Of those, the ones stopped early at a theta0 far from the target
    /// (ContactResult::provisional).
    unsigned int
    n_provisional_solves() const
    {
      return n_provisional;
    }

    /// Contact solves on the level-0 scene for first guesses so far.
    unsigned int
    n_coarse_solves() const
    {
      return n_coarse;
    }

    /// The largest q of the nips converged so far (P [N/mm] or u0 [mm]),
    /// 0 if none, and its theta0 [rad].
    double
    largest_converged() const;
    double
    largest_converged_theta() const;

    /// The slope d log q / d log theta0 of the secant from the converged
    /// nip nearest to @p target (in log q) to the nearest fully converged
    /// one far enough from it for the conformity error of q to stay small
    /// beside their difference (else the next nearest), 0 with fewer.
    double
    local_slope(const double target) const;

    /// The curvature d^2 log theta0 / d (log q)^2 of the converged nips,
    /// from the three spread widest in log q (0 with fewer, or too close
    /// together for the conformity error of q to stay small beside it).
    double
    local_curvature() const;

  private:
    struct Point
    {
      double theta;       ///< [rad]
      double q;           ///< P [N/mm] or u0 [mm]
      bool   provisional; ///< stopped short of the curve
    };

    /// The converged nips, nearest to @p target (in log q) first.
    std::vector<Point>
    nearest_first(const double target) const;

    /// The first theta0 to try for @p target: from Hertz and the thin
    /// layer.
    double
    first_guess(const double target) const;

    /// The first theta0 to try for a cold @p target: from the level-0
    /// scene if the scene is finer (its slope is kept for the second
    /// step), else first_guess().
    double
    cold_guess(const double target);

    /// The first theta0 to try for @p target once nips have converged:
    /// the inverse quadratic (log theta0 in log q) through three of them
    /// spread over the way to the target, or the power law of
    /// secant_guess() while there are fewer.
    double
    predict(const double target) const;

    /// The power-law (secant) estimate of theta0 for @p target from the
    /// two converged nips whose q are closest to it.
    double
    secant_guess(const double target) const;

    /// The next theta0 after @p theta for @p target: predict(), kept
    /// within a factor 2 of @p theta, inside the bracket of converged
    /// nips and below @p upper (a theta0 that failed, or the mesh's limit).
    double
    next_theta(const double target,
               const double theta,
               const double upper) const;

    /// The controlled quantity of a nip.
    double
    controlled(const ContactResult &r) const;

    /// The name of the controlled quantity, "P" or "u0".
    std::string
    quantity() const;

    /// The unit of the controlled quantity, with a leading space.
    std::string
    unit() const;

    /// The largest q reached and its theta0, for a refusal.
    std::string
    largest_reached() const;

    /// @p r marked failed, its message why @p target is out of reach.
    ContactResult
    refuse(ContactResult r, const double target, const std::string &why) const;

    /// Whether @p target lies beyond what q can reach below the theta0
    /// @p failed that just failed: above the largest converged nip below
    /// it times (failed / its theta0)^IterationControls::max_slope.
    bool
    beyond_steepest_rise(const double target, const double failed) const;
    /// @p r marked failed, its message why the iteration stopped short of
    /// @p target although the target may be within reach (it stalled on
    /// round-off or ran out of contact solves, every theta0 failed).
    ContactResult
    stop_short(ContactResult      r,
               const double       target,
               const std::string &why) const;

    /// The largest converged theta0 below @p theta, 0 if there is none.
    double
    converged_below(const double theta) const;

    /// Adds the converged nip (@p theta, @p q), keeping the order by theta.
    void
    remember(const double theta, const double q, const bool provisional);

    /// Why a target needing theta0 above @p theta_max, the mesh's largest
    /// nip, is refused.
    std::string
    beyond_mesh(const double theta_max) const;

    NipSolver                       &contact;
    const Parameters::AllParameters &parameters;
    const bool                       by_load;
    std::vector<Point>               converged; ///< sorted by theta
    unsigned int                     n_solves            = 0;
    unsigned int                     n_provisional       = 0;
    bool                             provisional_allowed = true;
    unsigned int                     n_coarse            = 0;
    /// The slope of log q against log theta0 at hint_target, 0 if none:
    /// the level-0 scene's at a cold target, or a coarser companion's
    /// (solve()'s guess_slope). It is the secant's slope while one nip of
    /// that target has converged: the chord to an earlier target's nip
    /// would miss the local slope by its curvature over that span.
    double slope_hint = 0, hint_target = 0;
    /// The converged nips of the target being solved.
    unsigned int n_at_target = 0;
    /// The curvature of log theta0 against log q on the level-0 scene
    /// (local_curvature()), 0 if none: added to the secant while two nips
    /// of hint_target have converged, where the power law alone misses
    /// the bend of the thin cover's curve by more than the tolerance.
    double curvature_hint = 0;
    /// Why the level-0 scene shows a cold target out of reach ("" if it
    /// does not): its largest converged q lies below half the target.
    std::string coarse_refusal;
  };

  /// The nip for @p target with a NipControl of its own (no sweep).
  ContactResult
  solve_controlled_nip(NipSolver                       &contact,
                       const Parameters::AllParameters &parameters,
                       const double                     target);
} // namespace rollnip

#endif
