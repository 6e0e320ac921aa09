#ifndef rollnip_material_hardness_h
#define rollnip_material_hardness_h

#include <string>

/**
 * Young's modulus of a rubber estimated from its indentation hardness
 * (doc/engineering_inputs.md, section 1). Pure functions: no parameter
 * handling, no output. All moduli in MPa.
 */
namespace rollnip
{
  namespace Hardness
  {
    enum class Scale
    {
      shore_a,     ///< ASTM D2240 / ISO 48-4 type A durometer
      irhd,        ///< International Rubber Hardness Degrees, ISO 48-2
      pusey_jones, ///< P&J plastometer indentation [1/100 mm], ISO 48-8
      shore_d      ///< ASTM D2240 / ISO 48-4 type D durometer
    };

    /// The scale named as in the parameter file: Shore A, Shore D, IRHD or
    /// P&J, in any case. Throws ExcMessage naming Material/Hardness scale
    /// for anything else.
    Scale
    scale_from_string(const std::string &name);

    /// The name of @p scale as written in the parameter file.
    std::string
    to_string(Scale scale);

    /// The readings on @p scale for which the relation used is published
    /// and checked (doc/engineering_inputs.md gives the sources).
    struct Range
    {
      double min, max;
    };
    Range
    validity_range(Scale scale);

    /// The readings on @p scale inside which the relation used was
    /// validated by its source (a narrower range than validity_range(),
    /// which only keeps the modulus finite): outside it rollnip warns.
    Range
    validated_range(Scale scale);

    /// Shore D through the Shore A equivalent S_A = S_D + 50 and the
    /// log-linear correlation log10 E = 0.0235 S_A - 0.6403 (E in MPa).
    double
    youngs_modulus_from_shore_d(double shore_d);

    /// The log-linear Shore A correlation log10 E = 0.0235 S - 0.6403.
    double
    youngs_modulus_log_linear(double shore_a);

    /// The Shore A reading Gent's relation gives for @p E [MPa] (E above
    /// Gent's value at 0; bisection on the monotone relation).
    double
    shore_a_from_modulus(double E);

    /// The spread of published correlations at one reading: the smallest
    /// and largest E [MPa] of Gent (1958), the ISO 48 IRHD relation and the
    /// log-linear fit, each where its reading is valid, at the reading's
    /// Shore A equivalent (the reading itself for Shore A and IRHD, S_D +
    /// 50 for Shore D, Gent's inverse of the ball relation for P&J), and
    /// the scale's own relation.
    struct Band
    {
      double low, high;
    };
    Band
    modulus_band(double value, Scale scale);

    /// Young's modulus E [MPa] from a reading @p value on @p scale; the
    /// reading must lie in validity_range(scale).
    double
    youngs_modulus(double value, Scale scale);

    /// Gent (1958): Shore A reading to E [MPa].
    double
    youngs_modulus_from_shore_a(double shore_a);

    /// ISO 48: IRHD to E [MPa] (probit of log10 E, 50 IRHD at
    /// log10 E = 0.364, 57 IRHD per decade at the midpoint).
    double
    youngs_modulus_from_irhd(double irhd);

    /// The ball-indentation relation behind ISO 48, F/E = 0.0038 R^0.65
    /// D^1.35, applied to the P&J test (3.175 mm ball, 1 kgf): P&J reading
    /// (indentation D in 1/100 mm) to E [MPa].
    double
    youngs_modulus_from_pusey_jones(double indentation);

    /// Where the relation for @p scale comes from, for the output.
    std::string
    source(Scale scale);

    /// Mooney-Rivlin constants for an incompressible solid of Young's
    /// modulus @p E: C1 + C2 = E/6 (G = E/3 = 2 (C1 + C2)), C2 = ratio C1.
    struct MooneyRivlin
    {
      double C1, C2;
    };
    MooneyRivlin
    mooney_rivlin_from_modulus(double E, double c2_over_c1);
  } // namespace Hardness
} // namespace rollnip

#endif
