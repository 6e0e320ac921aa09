#ifndef rollnip_solvers_tolerance_floor_h
#define rollnip_solvers_tolerance_floor_h

#include <rollnip/parameters.h>

#include <limits>
#include <string>
#include <vector>

namespace rollnip
{
  /**
   * Tolerances the iterations can meet in double precision
   * (doc/robustness.md). A relative tolerance below these would be met
   * only by chance: the iteration stalls on round-off and its failure
   * would read as a limit of the physics.
   */
  namespace ToleranceFloor
  {
    /// Newton's residual, increment and constraint tolerances and the
    /// conformity of the contact zone (|gap| / u0): 1e4 machine epsilon,
    /// about 2.2e-12, some 100 times the round-off these reach on the
    /// shipped scenes.
    constexpr double relative = 1e4 * std::numeric_limits<double>::epsilon();

    /// Contact/Control tolerance, on P or u0 from the contact solve: P is
    /// known to the conformity, which under control is at most
    /// IterationControls::control_conformity_fraction (0.1) of the
    /// control tolerance; 100 times the relative floor.
    constexpr double control = 100 * relative;

    /**
     * Clamps the tolerances of @p parameters below these floors (0
     * included) to them and returns one warning line per clamped entry,
     * naming it (without the "rollnip: warning: " prefix). Throws a
     * one-line message for Contact/Maximum iterations = 1 in a contact
     * scene and Mating roll/Maximum iterations = 1 with a covered mating
     * roll: their first iteration only measures the first guess, so no
     * nip could converge.
     */
    std::vector<std::string>
    apply(Parameters::AllParameters &parameters);

    /// The conformity residual that round-off of the gaps allows at
    /// indentation @p u0 [mm] on a roll of outer radius @p R0 [mm]: the
    /// coordinates carry epsilon R0, the residual is relative to u0 (10
    /// epsilon R0 / u0; the shipped scenes stall at 1 to 3 epsilon R0/u0).
    double
    conformity_round_off(double R0, double u0);
  } // namespace ToleranceFloor
} // namespace rollnip

#endif
