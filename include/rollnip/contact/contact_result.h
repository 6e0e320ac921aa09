#ifndef rollnip_contact_contact_result_h
#define rollnip_contact_contact_result_h

#include <string>
#include <vector>

namespace rollnip
{
  /// The checks and results of one solved nip (doc/intro.md, section 7).
  struct ContactResult
  {
    bool        converged = false;
    std::string message;
    double      theta0        = 0; ///< [rad]
    double      indentation   = 0; ///< u0 [mm]
    double      nip_load      = 0; ///< P, two-sided [N/mm]
    double      conformity    = 0; ///< max |gap| / u0 over the contact zone
    double      penetration   = 0; ///< max(-gap, 0) / u0 outside the zone
    double      min_pressure  = 0; ///< min f at the parameters [MPa]
    double      peak_pressure = 0; ///< max f [MPa]
    /// Deformed contact half-length along the surface, and the half-chord
    /// (the x2 coordinate of the deformed edge point) [mm].
    double       half_arc = 0, half_chord = 0;
    unsigned int iterations = 0;
    /// Stopped before the conformity tolerance because theta0 misses the
    /// control's target by far more than the conformity residual left
    /// (NipSolver::ControlGoal): good for the next secant step, never an
    /// answer.
    bool                provisional = false;
    std::vector<double> knots;  ///< reference angles of the pressure basis
    std::vector<double> values; ///< f at the knots [MPa]

    /// Against a covered mating roll (TwoRollContact); indentation is then
    /// the approach of the two centres.
    bool   two_rolls        = false;
    double roll_indentation = 0; ///< of this roll's surface [mm]
    double mate_indentation = 0; ///< of the mating roll's surface [mm]
    double mate_nip_load    = 0; ///< P from the mating roll's load [N/mm]
    /// P from the normal stress on the mating roll's surface [N/mm].
    double       mate_load_from_traction = 0;
    double       mate_penetration = 0; ///< of its nodes into this roll, / u0
    unsigned int outer_iterations = 0; ///< of the two-roll iteration
  };

} // namespace rollnip

#endif
