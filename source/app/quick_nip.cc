#include <deal.II/base/exceptions.h>

#include <rollnip/app/quick_nip.h>
#include <rollnip/output/units.h>
#include <rollnip/run_errors.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include <unistd.h>

namespace rollnip
{
  namespace
  {
    using dealii::ExcMessage;

    const char *const quick_usage =
      "Usage: rollnip nip --diameter D --cover T --hardness H --mate D2 "
      "--load P [options]\n"
      "\n"
      "The nip of a rubber-covered roll against a rigid (steel) roll, from\n"
      "the numbers a roll engineer has; prints the nip report (width 2b,\n"
      "indentation, peak and mean pressure, dwell time). The scene is that\n"
      "of parameters/engineering_nip.prm (a 90 deg sector, mesh level 2,\n"
      "load control); --write-prm writes it as a parameter file, which\n"
      "`rollnip FILE.prm` runs to the same numbers.\n"
      "\n"
      "  --diameter D    outer diameter of the covered roll (mm, cm, m or in;\n"
      "                  a bare number is mm), e.g. 400 or 15.75in\n"
      "  --cover T       cover thickness, e.g. 20mm or 0.75in\n"
      "  --hardness H    cover hardness with its scale: 70A (Shore A, also a\n"
      "                  bare number), 60IRHD, 120PJ (Pusey & Jones), 50D\n"
      "                  (Shore D); the modulus is estimated from it\n"
      "  --modulus E     instead of --hardness: Young's modulus (MPa, kPa or\n"
      "                  psi), e.g. 4.5MPa\n"
      "  --mate D2       diameter of the rigid mating roll, or flat\n"
      "  --load P        line load(s) with the unit: kN/m, N/mm or pli\n"
      "                  (lbf/in), e.g. 40kN/m or 20,40,60kN/m\n"
      "  --speed V       surface speed for the dwell time: m/min, m/s or fpm,\n"
      "                  e.g. 600m/min\n"
      "  --output DIR    results directory (default output/nip)\n"
      "  --write-prm F   also write the equivalent parameter file F\n"
      "  -h, --help      this text\n"
      "\n"
      "A value and its unit may also be two arguments (--load 40 kN/m) or\n"
      "one with '=' (--load=40kN/m).\n";

    std::string
    lower(std::string s)
    {
      std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) {
        return static_cast<char>(std::tolower(c));
      });
      return s;
    }

    /// @p s without blanks, lower case: "Shore A" and "shorea" match.
    std::string
    squeezed(const std::string &s)
    {
      std::string out;
      for (const char c : lower(s))
        if (!std::isspace(static_cast<unsigned char>(c)))
          out += c;
      return out;
    }

    /// The factor of @p unit in @p table (keys squeezed), or an error naming
    /// @p flag and the units allowed.
    double
    factor(const std::map<std::string, double> &table,
           const std::string                   &unit,
           const std::string                   &flag,
           const std::string                   &allowed)
    {
      const auto it = table.find(squeezed(unit));
      AssertThrow(it != table.end(),
                  ExcMessage(flag + ": unknown unit '" + unit + "' (" +
                             allowed + ")"));
      return it->second;
    }

    /// @p x with enough digits that the file reproduces it.
    std::string
    exact(const double x)
    {
      std::ostringstream s;
      s << std::setprecision(12) << x;
      return s.str();
    }
  } // namespace

  /// The quick form's flags with their units, converted with the
  /// constants of the one unit table (output/units.h).
  namespace QuickUnits
  {
    Quantity
    split(const std::string &text, const std::string &flag)
    {
      char        *end = nullptr;
      const double x   = std::strtod(text.c_str(), &end);
      AssertThrow(end != text.c_str() && std::isfinite(x),
                  ExcMessage(flag + ": '" + text +
                             "' does not start with a number"));
      Quantity q;
      q.value = x;
      q.unit  = std::string(end);
      q.unit.erase(0, q.unit.find_first_not_of(' '));
      q.unit.erase(q.unit.find_last_not_of(' ') + 1);
      return q;
    }

    double
    length_to_mm(const std::string &unit, const std::string &flag)
    {
      static const std::map<std::string, double> table = {
        {"", 1.},
        {"mm", 1.},
        {"cm", 10.},
        {"m", 1000.},
        {"in", Units::mm_per_inch},
        {"inch", Units::mm_per_inch}};
      return factor(table, unit, flag, "mm, cm, m or in");
    }

    double
    speed_to_m_per_min(const std::string &unit, const std::string &flag)
    {
      static const std::map<std::string, double> table = {
        {"m/min", 1.},
        {"mpm", 1.},
        {"m/s", Units::m_per_min_per_m_per_s},
        {"fpm", Units::m_per_min_per_fpm},
        {"ft/min", Units::m_per_min_per_fpm}};
      return factor(table, unit, flag, "m/min, m/s or fpm");
    }

    double
    modulus_to_mpa(const std::string &unit, const std::string &flag)
    {
      static const std::map<std::string, double> table = {
        {"mpa", 1.}, {"n/mm2", 1.}, {"kpa", 1e-3}, {"psi", Units::mpa_per_psi}};
      return factor(table, unit, flag, "MPa, kPa or psi");
    }

    std::string
    line_load_unit(const std::string &unit, const std::string &flag)
    {
      static const std::map<std::string, std::string> table = {
        {"n/mm", "N/mm"},
        {"kn/m", "kN/m"},
        {"pli", "pli"},
        {"lbf/in", "pli"},
        {"lb/in", "pli"}};
      const auto it = table.find(squeezed(unit));
      AssertThrow(it != table.end(),
                  ExcMessage(flag + ": " +
                             (unit.empty() ? std::string("give the unit")
                                           : "unknown unit '" + unit + "'") +
                             " (kN/m, N/mm or pli, e.g. 40kN/m)"));
      return it->second;
    }
  } // namespace QuickUnits

  namespace
  {
    /// The flags of the quick form with their values, as given.
    using Flags = std::map<std::string, std::string>;

    const std::vector<std::string> known_flags = {"--diameter",
                                                  "--cover",
                                                  "--hardness",
                                                  "--modulus",
                                                  "--mate",
                                                  "--load",
                                                  "--speed",
                                                  "--output",
                                                  "--write-prm"};

    /// Whether @p text is a unit on its own (the second word of "40 kN/m").
    bool
    is_unit_word(const std::string &text)
    {
      return !text.empty() && text.rfind("--", 0) != 0 &&
             !std::isdigit(static_cast<unsigned char>(text[0])) &&
             text[0] != '.' && text[0] != '-' && text[0] != '+';
    }

    Flags
    read_flags(const std::vector<std::string> &args)
    {
      Flags flags;
      for (std::size_t i = 0; i < args.size(); ++i)
        {
          std::string       flag = args[i], value;
          const std::size_t eq   = flag.find('=');
          if (flag.rfind("--", 0) == 0 && eq != std::string::npos)
            {
              value = flag.substr(eq + 1);
              flag  = flag.substr(0, eq);
            }
          AssertThrow(std::find(known_flags.begin(), known_flags.end(), flag) !=
                        known_flags.end(),
                      ExcMessage("nip: unknown " +
                                 std::string(flag.rfind("-", 0) == 0
                                               ? "option '"
                                               : "argument '") +
                                 flag + "' (see rollnip nip --help)"));
          AssertThrow(flags.count(flag) == 0,
                      ExcMessage(flag + " is given twice"));
          if (eq == std::string::npos)
            {
              AssertThrow(i + 1 < args.size() &&
                            args[i + 1].rfind("--", 0) != 0,
                          ExcMessage(flag + " needs a value (see rollnip nip "
                                            "--help)"));
              value = args[++i];
            }
          // "--load 40 kN/m": the unit as a word of its own.
          if (i + 1 < args.size() && is_unit_word(args[i + 1]) &&
              flag != "--output" && flag != "--write-prm" &&
              std::isdigit(static_cast<unsigned char>(value.back())))
            value += " " + args[++i];
          flags[flag] = value;
        }
      for (const char *required : {"--diameter", "--cover", "--mate", "--load"})
        AssertThrow(flags.count(required),
                    ExcMessage(std::string("nip: ") + required +
                               " is missing (see rollnip nip --help)"));
      AssertThrow(flags.count("--hardness") + flags.count("--modulus") == 1,
                  ExcMessage("nip: give --hardness or --modulus (one of "
                             "them)"));
      return flags;
    }

    /// "   # 15.75in": the value of @p flag as given, when it had a unit.
    std::string
    as_given(const Flags &flags, const std::string &flag)
    {
      const std::string &text = flags.at(flag);
      return QuickUnits::split(text, flag).unit.empty() ? "" : "   # " + text;
    }

    /// A positive length [mm] of @p flag.
    double
    length(const Flags &flags, const std::string &flag)
    {
      const auto   q  = QuickUnits::split(flags.at(flag), flag);
      const double mm = q.value * QuickUnits::length_to_mm(q.unit, flag);
      AssertThrow(mm > 0,
                  ExcMessage(flag + ": '" + flags.at(flag) +
                             "' must be a positive length"));
      return mm;
    }

    /// The Material entries of --hardness or --modulus.
    std::string
    material_entries(const Flags &flags)
    {
      std::ostringstream s;
      if (flags.count("--modulus"))
        {
          const auto q = QuickUnits::split(flags.at("--modulus"), "--modulus");
          const double E =
            q.value * QuickUnits::modulus_to_mpa(q.unit, "--modulus");
          AssertThrow(E > 0,
                      ExcMessage("--modulus: '" + flags.at("--modulus") +
                                 "' must be positive"));
          s << "  # Young's modulus " << flags.at("--modulus")
            << ": C1 + C2 = E/6\n"
            << "  set C1 = " << exact(E / 6.) << "\n  set C2 = 0\n";
          return s.str();
        }
      const auto q = QuickUnits::split(flags.at("--hardness"), "--hardness");
      static const std::map<std::string, std::string> scales = {
        {"", "Shore A"},
        {"a", "Shore A"},
        {"shorea", "Shore A"},
        {"sha", "Shore A"},
        {"d", "Shore D"},
        {"shored", "Shore D"},
        {"irhd", "IRHD"},
        {"pj", "P&J"},
        {"p&j", "P&J"}};
      const auto it = scales.find(squeezed(q.unit));
      AssertThrow(it != scales.end(),
                  ExcMessage("--hardness: unknown scale '" + q.unit +
                             "' (70A or 70 for Shore A, 50D, 60IRHD, 120PJ)"));
      s << "  # The modulus is estimated from the hardness "
           "(doc/engineering_inputs.md).\n"
        << "  set Hardness       = " << exact(q.value) << "\n"
        << "  set Hardness scale = " << it->second << "\n"
        << "  set C2/C1 ratio    = 0\n";
      return s.str();
    }

    /// The Contact entries of --mate, --load and --speed.
    std::string
    contact_entries(const Flags &flags)
    {
      std::ostringstream s;
      // The unit after the last value: "20,40,60kN/m" or "20, 40, 60 kN/m".
      const std::string &text = flags.at("--load");
      const std::size_t  unit_start =
        text.find_first_not_of("0123456789.eE+-, ");
      const std::string unit =
        QuickUnits::line_load_unit(unit_start == std::string::npos
                                     ? ""
                                     : text.substr(unit_start),
                                   "--load");
      std::string        values;
      std::istringstream list(text.substr(0, unit_start));
      for (std::string v; std::getline(list, v, ',');)
        {
          const auto q = QuickUnits::split(v, "--load");
          AssertThrow(q.value > 0 && q.unit.empty(),
                      ExcMessage("--load: '" + v +
                                 "' must be a positive number"));
          values += (values.empty() ? "" : ", ") + exact(q.value);
        }
      s << "  set Mode              = load\n"
        << "  set Load unit         = " << unit << "\n"
        << "  set Values            = " << values << "\n";
      if (squeezed(flags.at("--mate")) == "flat" ||
          squeezed(flags.at("--mate")) == "inf")
        s << "  set Indenter radius   = inf\n";
      else
        s << "  set Indenter diameter = " << exact(length(flags, "--mate"))
          << as_given(flags, "--mate") << "\n";
      if (flags.count("--speed"))
        {
          const auto   q = QuickUnits::split(flags.at("--speed"), "--speed");
          const double v =
            q.value * QuickUnits::speed_to_m_per_min(q.unit, "--speed");
          AssertThrow(!q.unit.empty() && v > 0,
                      ExcMessage("--speed: '" + flags.at("--speed") +
                                 "' must be a positive speed with its unit "
                                 "(m/min, m/s or fpm)"));
          s << "  set Surface speed     = " << exact(v) << "   # m/min; "
            << flags.at("--speed") << "\n";
        }
      s << "  set Compare with linear theory = false\n";
      return s.str();
    }
  } // namespace

  bool
  is_quick_nip(const int argc, char **argv)
  {
    return argc > 1 && std::string(argv[1]) == "nip";
  }

  std::string
  quick_nip_parameters(const std::vector<std::string> &args)
  {
    const Flags  flags    = read_flags(args);
    const double diameter = length(flags, "--diameter");
    const double cover    = length(flags, "--cover");
    AssertThrow(cover < diameter / 2,
                ExcMessage("--cover: the cover (" + exact(cover) +
                           " mm) must be thinner than the roll's radius (" +
                           exact(diameter / 2) + " mm)"));
    std::ostringstream s;
    s << "# The nip of `rollnip nip";
    for (const auto &a : args)
      s << ' ' << (a.find(' ') == std::string::npos ? a : "'" + a + "'");
    s << "`\n# (the scene of parameters/engineering_nip.prm).\n"
      << "subsection Geometry\n"
      << "  set Roll diameter   = " << exact(diameter)
      << as_given(flags, "--diameter") << "\n"
      << "  set Cover thickness = " << exact(cover)
      << as_given(flags, "--cover") << "\n"
      << "  set Sector angle    = 90\nend\n\n"
      << "subsection Mesh\n  set Radial cells          = 8\n"
      << "  set Circumferential cells = 18\n"
      << "  set Global refinements    = 2\nend\n\n"
      << "subsection Material\n"
      << material_entries(flags) << "end\n\n"
      << "subsection Contact\n"
      << contact_entries(flags) << "end\n\n"
      << "subsection Output\n"
      << "  set Directory      = "
      << (flags.count("--output") ? flags.at("--output") : "output/nip")
      << "\n  set Write VTU      = true\n"
      << "  set VTU every step = false\nend\n";
    return s.str();
  }

  namespace
  {
    /// This process's parameter file of the quick form, removed at exit.
    std::string temporary_file;

    void
    remove_temporary_file()
    {
      if (!temporary_file.empty())
        std::remove(temporary_file.c_str());
    }

    void
    write_text(const std::string &name,
               const std::string &text,
               const std::string &what)
    {
      std::ofstream out(name);
      out << text;
      out.close();
      AssertThrow(out.good(),
                  ExcMessage(what + ": cannot write '" + name + "'"));
    }
  } // namespace

  int
  prepare_quick_nip(const int    argc,
                    char       **argv,
                    const bool   root,
                    std::string &file)
  {
    const std::vector<std::string> args(argv + 2, argv + argc);
    if (std::find(args.begin(), args.end(), "--help") != args.end() ||
        std::find(args.begin(), args.end(), "-h") != args.end())
      {
        if (root)
          std::cout << quick_usage;
        return 0;
      }
    try
      {
        const std::string text = quick_nip_parameters(args);
        const auto        named =
          std::find_if(args.begin(), args.end(), [](const std::string &a) {
            return a.rfind("--write-prm", 0) == 0;
          });
        if (root && named != args.end())
          {
            const std::string name =
              named->size() > 11 ? named->substr(12) : *std::next(named);
            write_text(name, text, "--write-prm");
            std::cout << "nip: the parameter file is " << name << std::endl;
          }
        // Every process reads its own copy: none waits for another's.
        temporary_file =
          (std::filesystem::temp_directory_path() /
           ("rollnip-nip-" + std::to_string(::getpid()) + ".prm"))
            .string();
        write_text(temporary_file, text, "nip: the parameter file");
        std::atexit(remove_temporary_file);
        file = temporary_file;
        return -1;
      }
    catch (const std::exception &e)
      {
        if (root)
          std::cerr << "rollnip: error: " << one_line_message(e) << std::endl;
        return 1;
      }
  }
} // namespace rollnip
