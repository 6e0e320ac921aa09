#ifndef rollnip_app_quick_nip_h
#define rollnip_app_quick_nip_h

#include <string>
#include <vector>

/**
 * The quick form of a nip, `rollnip nip --diameter 400 --cover 20
 * --hardness 70A --mate 300 --load 40kN/m --speed 600m/min`: the flags
 * become the parameter file of the engineering scene
 * (parameters/engineering_nip.prm), which the ordinary run then solves, so
 * that the quick answer and the file it can write (--write-prm) give the
 * same numbers. Read before MPI starts, like the rest of the command line.
 */
namespace rollnip
{
  /// Whether the command line is the quick form: its first argument is
  /// `nip`.
  bool
  is_quick_nip(int argc, char **argv);

  /// The parameter file text of the quick form's flags @p args (those
  /// after `nip`). Throws ExcMessage naming the flag on a bad or missing
  /// flag or value; the unit of every value is converted here.
  std::string
  quick_nip_parameters(const std::vector<std::string> &args);

  /**
   * Reads the quick form's flags, writes its parameter file for this
   * process (and, on the launch root, to --write-prm FILE) and returns
   * its name in @p file, to be run as any parameter file. Returns the exit
   * code when the run ends here (--help, a bad flag: one line `rollnip:
   * error: ...` naming it), else -1. On the launch root (@p root) the
   * help, errors and the file's name are printed.
   */
  int
  prepare_quick_nip(int argc, char **argv, bool root, std::string &file);

  /// Length, line load, speed and modulus units of the quick form's values
  /// (a value and its unit, e.g. "40kN/m", "9.5 in", "1969fpm").
  namespace QuickUnits
  {
    /// A number and the unit written after it (the unit empty if none).
    struct Quantity
    {
      double      value = 0;
      std::string unit;
    };

    /// Splits "40kN/m" or "40 kN/m" into 40 and "kN/m"; throws
    /// ExcMessage naming @p flag if it does not start with a number.
    Quantity
    split(const std::string &text, const std::string &flag);

    /// The factor to mm of a length unit (mm, cm, m, in; empty: mm);
    /// throws naming @p flag for another unit.
    double
    length_to_mm(const std::string &unit, const std::string &flag);

    /// The factor to m/min of a speed unit (m/min, m/s, fpm, ft/min).
    double
    speed_to_m_per_min(const std::string &unit, const std::string &flag);

    /// The factor to MPa of a modulus unit (MPa, kPa, psi).
    double
    modulus_to_mpa(const std::string &unit, const std::string &flag);

    /// The Contact/Load unit spelling of a line load unit (N/mm, kN/m,
    /// pli, lbf/in as pli), matched case-insensitively.
    std::string
    line_load_unit(const std::string &unit, const std::string &flag);
  } // namespace QuickUnits
} // namespace rollnip

#endif
