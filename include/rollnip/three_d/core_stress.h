#ifndef rollnip_three_d_core_stress_h
#define rollnip_three_d_core_stress_h

#include <ostream>
#include <string>
#include <vector>

/**
 * The elastic core's bending stresses (Three d/Core = elastic,
 * doc/three_d.md): the axial Cauchy stress sigma_zz of the 3D tube at every
 * plane of its nodes, as its fibre values, against beam theory M c / I
 * with the bending moment M(z) of a simply supported beam under the run's
 * own line load.
 */
namespace rollnip
{
  namespace three_d
  {
    class SliceBody;

    /// sigma_zz of the tube at one plane z. The 3D values are the least-
    /// squares plane sigma_zz = mean + slope x over the tube's cross-section
    /// (the quadrature points of its faces in the plane, from the cells on
    /// both sides), read at the fibres x = +-R1, +-Ri: the nip lies at
    /// x > 0, so its side is compressed.
    struct CoreBendingStress
    {
      double z         = 0; ///< [mm]
      double moment    = 0; ///< beam theory's M(z) from the line load [N mm]
      double outer_nip = 0, outer_far = 0; ///< at x = R1 and -R1 [MPa]
      double bore_nip = 0, bore_far = 0;   ///< at x = Ri and -Ri [MPa]
      double beam_outer = 0; ///< -M R1 / I, beam theory at x = R1 [MPa]
      double beam_bore  = 0; ///< -M Ri / I at x = Ri [MPa]
      double mean       = 0; ///< the fit's mean, axial force / area [MPa]
      /// Root mean square of sigma_zz about the fitted plane [MPa]: what
      /// of the stress is not the beam's linear distribution.
      double deviation = 0;
    };

    /**
     * The tube's bending stresses at every plane of its vertices from the
     * middle of the face z = 0 to the journal. M(z) is that of the beam
     * simply supported at +-Bearing distance under the nodal line loads of
     * SliceBody::line_load_profile() (the full nip's, symmetric about
     * z = 0); I = pi/4 (R1^4 - Ri^4).
     */
    std::vector<CoreBendingStress>
    core_bending_stress(const SliceBody &body);

    /// @p stresses as CSV with a header, one row per plane.
    void
    write_core_stress(const std::string                    &path,
                      const std::vector<CoreBendingStress> &stresses);

    /// The middle plane's values as "key = value" lines of summary.txt.
    void
    write_core_stress_summary(std::ostream            &out,
                              const CoreBendingStress &middle);
  } // namespace three_d
} // namespace rollnip

#endif
