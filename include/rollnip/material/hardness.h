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
      shore_a,    ///< ASTM D2240 / ISO 48-4 type A durometer
      irhd,       ///< International Rubber Hardness Degrees, ISO 48-2
      pusey_jones ///< P&J plastometer indentation [1/100 mm], ISO 48-8
    };

    /// The scale named as in the parameter file: Shore A, IRHD or P&J.
    /// Throws ExcMessage naming Material/Hardness scale for anything else.
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
