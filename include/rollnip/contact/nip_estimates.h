#ifndef rollnip_contact_nip_estimates_h
#define rollnip_contact_nip_estimates_h

#include <rollnip/scene/scene_description.h>

namespace rollnip
{
  /**
   * The closed-form nip estimates of a contact scene (doc/intro.md section
   * 7, doc/two_rolls.md): first guesses of the contact iteration and the
   * reference columns of the nip characteristic. The mating body is the
   * scene's counter surface: a rigid circle or plane, or the covered
   * mating roll, whose cover adds its compliance to the roll's.
   */
  namespace NipEstimates
  {
    /// R with 1/R = 1/R0 + 1/R_mate [mm] (R0 for a flat mate).
    double
    effective_radius(const SceneDescription &scene);

    /// E* of plane-strain Hertz [MPa], 1/E* = sum over the deformable
    /// covers of 1/(4 G) (incompressible), G of the outer layer.
    double
    contact_modulus(const SceneDescription &scene);

    /// 3 int_0^h (h - s)^2 / G(s) ds [mm^3/MPa] of one cover, s from the
    /// core out through its layers: h^3 / G for one layer.
    double
    layered_compliance(const RollDescription &roll);

    /// Sum over the deformable covers of layered_compliance(): the thin
    /// bonded incompressible layer has P = 2 b^5 / (15 R sum h^3/G).
    double
    thin_layer_compliance(const SceneDescription &scene);

    /// P of Hertz for the contact half-width @p b [N/mm].
    double
    hertz_load(const SceneDescription &scene, const double b);

    /// The reference angle [rad] of a covered mating roll of outer radius
    /// @p Rm whose contact edge lies at the same distance from the line of
    /// centres as that of the roll of outer radius @p R0 at @p theta0
    /// (equal undeformed chords).
    double
    mate_nip_angle(const double R0, const double Rm, const double theta0);

    /// P of the thin layer(s) for the contact half-width @p b [N/mm].
    double
    thin_layer_load(const SceneDescription &scene, const double b);

    /// The half-width b [mm] Hertz gives at the line load @p P [N/mm]:
    /// the inverse of hertz_load(), b = sqrt(4 P R / (pi E*)).
    double
    hertz_half_width(const SceneDescription &scene, double P);

    /// The thin layer's half-width b [mm] at @p P: the inverse of
    /// thin_layer_load().
    double
    thin_layer_half_width(const SceneDescription &scene, double P);

    /// Peak pressures [MPa] at the line load @p P over the half-width
    /// @p b: Hertz's elliptic profile, 2 P / (pi b), and the thin layer's
    /// (b^2 - x^2)^2 profile, 15 P / (16 b).
    double
    hertz_peak_pressure(double P, double b);
    double
    thin_layer_peak_pressure(double P, double b);
  } // namespace NipEstimates
} // namespace rollnip

#endif
