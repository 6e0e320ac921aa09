#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <rollnip/engineering_inputs.h>
#include <rollnip/material/hardness.h>
#include <rollnip/material/material_table.h>
#include <rollnip/output/units.h>
#include <rollnip/parameter_entries.h>
#include <rollnip/scene/scene_description.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <vector>

namespace rollnip
{
  namespace EngineeringInputs
  {
    namespace
    {
      /// An entry whose empty default means "not given".
      void
      declare_optional(ParameterHandler  &prm,
                       const std::string &name,
                       const std::string &doc)
      {
        prm.declare_entry(name, "", Patterns::Anything(), doc);
      }

      /// @p text as a number if all of it is one, else NaN.
      double
      whole_number(const std::string &text)
      {
        std::size_t used  = 0;
        double      value = 0;
        try
          {
            value = std::stod(text, &used);
          }
        catch (...)
          {
            used = 0;
          }
        return used == text.size() && used > 0
                 ? value
                 : std::numeric_limits<double>::quiet_NaN();
      }

      /// The number in entry @p name of subsection @p section (NaN when the
      /// entry is empty); 'inf' only if @p allow_inf.
      double
      optional_number(ParameterHandler  &prm,
                      const std::string &section,
                      const std::string &name,
                      const bool         allow_inf = false)
      {
        const std::string text = prm.get(name);
        if (text.empty())
          return std::numeric_limits<double>::quiet_NaN();
        if (allow_inf && (text == "inf" || text == "infinity"))
          return std::numeric_limits<double>::infinity();
        const double value = whole_number(text);
        AssertThrow(std::isfinite(value) && value > 0,
                    ExcMessage(
                      section + "/" + name + " must be a positive number" +
                      (allow_inf ? " or 'inf'" : "") + ", got '" + text + "'"));
        return value;
      }

      /// Whether the entry @p name still has the value @p default_value
      /// (compared as numbers): the other form of an input was not used.
      bool
      at_default(ParameterHandler  &prm,
                 const std::string &name,
                 const double       default_value)
      {
        return std::strtod(prm.get(name).c_str(), nullptr) == default_value;
      }
    } // namespace

    void
    declare_geometry(ParameterHandler &prm)
    {
      declare_optional(prm,
                       "Roll diameter",
                       "Outer diameter of the covered roll [mm], with Cover "
                       "thickness instead of Inner radius and Outer radius. "
                       "Allowed: empty (use the radii) or a positive number");
      declare_optional(prm,
                       "Cover thickness",
                       "Thickness of the rubber cover [mm], with Roll "
                       "diameter. Allowed: empty or a positive number below "
                       "half the Roll diameter");
    }

    void
    parse_geometry(ParameterHandler &prm, Parameters::Geometry &geometry)
    {
      const double D = optional_number(prm, "Geometry", "Roll diameter");
      const double t = optional_number(prm, "Geometry", "Cover thickness");
      geometry.from_diameters = !std::isnan(D) || !std::isnan(t);
      if (!geometry.from_diameters)
        return;
      AssertThrow(!std::isnan(D) && !std::isnan(t),
                  ExcMessage("Geometry/Roll diameter and Geometry/Cover "
                             "thickness go together: give both"));
      // The radii's defaults (47.2, 60.7 mm): anything else was set.
      AssertThrow(at_default(prm, "Inner radius", 47.2) &&
                    at_default(prm, "Outer radius", 60.7),
                  ExcMessage("Geometry: give either Roll diameter and Cover "
                             "thickness or Inner radius and Outer radius, "
                             "not both"));
      AssertThrow(t < 0.5 * D,
                  ExcMessage("Geometry/Cover thickness (" +
                             Parameters::number(t) +
                             " mm) must be less than half the Roll diameter (" +
                             Parameters::number(D) + " mm)"));
      geometry.outer_radius = 0.5 * D;
      geometry.inner_radius = 0.5 * D - t;
    }

    void
    declare_material(ParameterHandler &prm)
    {
      declare_optional(
        prm,
        "Hardness",
        "Hardness of the cover on Hardness scale, instead of C1 and C2: "
        "Young's modulus E is estimated from it (an estimate: see "
        "doc/engineering_inputs.md) and C1 + C2 = E/6; for a layered cover "
        "one value per layer, from the core out. Allowed: empty (use C1, "
        "C2) or numbers within the scale's range (Shore A 20 to 95, Shore D "
        "30 to 80, IRHD 10 to 95, P&J 5 to 300)");
      prm.declare_entry("Hardness scale",
                        "Shore A",
                        Patterns::Anything(),
                        "Scale of Hardness, any case. Allowed: Shore A (Gent "
                        "1958), Shore D (log-linear correlation), IRHD (ISO "
                        "48) or P&J (Pusey & Jones, indentation in 1/100 mm)");
      Parameters::declare_documented(
        prm,
        "C2/C1 ratio",
        "0",
        Patterns::Double(0.),
        "Split of E/6 between C1 and C2 when Hardness is given; 0 is "
        "neo-Hookean (in-plane results depend on C1 + C2 only)");
    }

    namespace
    {
      /// The readings of Material/Hardness, one per layer, each a number
      /// within the range of its scale's relation; a reading outside the
      /// range its source validated is warned about (rank 0).
      std::vector<double>
      hardness_readings(const std::string &text, const Hardness::Scale scale)
      {
        const Hardness::Range range = Hardness::validity_range(scale);
        const Hardness::Range valid = Hardness::validated_range(scale);
        std::vector<double>   readings;
        for (const auto &item : Utilities::split_string_list(text))
          {
            const double value = whole_number(item);
            AssertThrow(!std::isnan(value),
                        ExcMessage("Material/Hardness = '" + item +
                                   "' is not a number (the scale goes in "
                                   "Material/Hardness scale)"));
            AssertThrow(value >= range.min && value <= range.max,
                        ExcMessage("Material/Hardness = '" + item + "' " +
                                   Hardness::to_string(scale) +
                                   " is outside the range of its modulus "
                                   "relation, " +
                                   Parameters::number(range.min) + " to " +
                                   Parameters::number(range.max)));
            if ((value < valid.min || value > valid.max) &&
                Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
              std::cerr << "rollnip: warning: Material/Hardness = " << item
                        << ' ' << Hardness::to_string(scale) << " is outside "
                        << valid.min << " to " << valid.max << ", where "
                        << Hardness::source(scale)
                        << " was validated: the modulus is a rougher "
                           "estimate (doc/engineering_inputs.md)"
                        << std::endl;
            readings.push_back(value);
          }
        return readings;
      }
    } // namespace

    void
    parse_material(ParameterHandler &prm, Parameters::Material &material)
    {
      const std::string text = prm.get("Hardness");
      const auto scale = Hardness::scale_from_string(prm.get("Hardness scale"));
      material.hardness_modulus = 0;
      material.hardness_description.clear();
      material.surface_hardness = 0;
      material.hardness_scale   = Hardness::to_string(scale);
      if (text.empty())
        return;
      AssertThrow(at_default(prm, "C1", 0.25) && at_default(prm, "C2", 0.25),
                  ExcMessage("Material: give either Hardness or C1 and C2, "
                             "not both"));
      const std::vector<double> readings = hardness_readings(text, scale);
      const std::size_t         n_layers =
        std::max<std::size_t>(1, material.layer_thicknesses.size());
      AssertThrow(readings.size() == n_layers,
                  ExcMessage(
                    "Material/Hardness has " + std::to_string(readings.size()) +
                    " value(s) but the cover has " + std::to_string(n_layers) +
                    " layer(s) (Material/Layer thicknesses): give "
                    "one hardness per layer, from the core out"));
      const double ratio = prm.get_double("C2/C1 ratio");
      material.layer_C1.clear();
      material.layer_C2.clear();
      std::string readings_text;
      for (const double value : readings)
        {
          const double E = Hardness::youngs_modulus(value, scale);
          const auto   c = Hardness::mooney_rivlin_from_modulus(E, ratio);
          material.layer_C1.push_back(c.C1);
          material.layer_C2.push_back(c.C2);
          // The surface layer's modulus is the one the nip report quotes.
          material.hardness_modulus = E;
          material.surface_hardness = value;
          readings_text +=
            (readings_text.empty() ? "" : ", ") + Parameters::number(value);
        }
      material.hardness_description =
        readings_text + " " + Hardness::to_string(scale) +
        (readings.size() > 1 ? " (layers from the core out)" : "") + ", " +
        Hardness::source(scale);
    }

    void
    declare_contact(ParameterHandler &prm)
    {
      declare_optional(prm,
                       "Indenter diameter",
                       "Diameter of the mating rigid roll [mm] instead of "
                       "Indenter radius; 'inf' for a flat plane. Allowed: "
                       "empty (use the radius), a positive number or inf");
      prm.declare_entry("Load unit",
                        "N/mm",
                        Patterns::Anything(),
                        "Unit of the loads in Values (Mode = load) and in "
                        "the nip report, any case. Allowed: N/mm, kN/m (the "
                        "same number), pli (pound-force per linear inch, "
                        "0.17512684 N/mm), or a total force N, kN or lbf over "
                        "the roll's Face length");
      declare_optional(prm,
                       "Face length",
                       "Loaded face length of the roll [mm], with Load unit "
                       "= N or kN (a total force): the line load is the "
                       "force over this length. Allowed: empty or a "
                       "positive number");
      Parameters::declare_documented(
        prm,
        "Surface speed",
        "0",
        Patterns::Anything(),
        "Surface speed of the roll for the dwell time 2b / v in the nip "
        "report; 0: not reported. Allowed: a number >= 0 in m/min, or with "
        "a unit: m/min, m/s or fpm (e.g. 1969 fpm), any case");
    }

    void
    parse_contact(ParameterHandler &prm, Parameters::Contact &contact)
    {
      contact.load_unit = LineLoadUnit::from_string(
        prm.get("Load unit"), optional_number(prm, "Contact", "Face length"));
      contact.surface_speed =
        Units::speed_in_m_per_min(prm.get("Surface speed"));
      if (contact.mode == Parameters::ContactMode::load)
        for (double &v : contact.values)
          v *= contact.load_unit.to_n_per_mm;
      const double D =
        optional_number(prm, "Contact", "Indenter diameter", true);
      if (std::isnan(D))
        return;
      AssertThrow(at_default(prm, "Indenter radius", 76.2),
                  ExcMessage("Contact: give either Indenter diameter or "
                             "Indenter radius, not both"));
      contact.indenter_radius = 0.5 * D;
      contact.keys_set_without_mode |=
        contact.mode == Parameters::ContactMode::none;
    }

    void
    check_modulus(const Parameters::Material &material,
                  const std::string          &prefix)
    {
      // The layer furthest outside the range of rubbers.
      const MaterialTable layers(material);
      double              G = layers[0].shear_modulus();
      for (unsigned int j = 1; j < layers.n_layers(); ++j)
        {
          const double Gj = layers[j].shear_modulus();
          if (std::abs(std::log(Gj)) > std::abs(std::log(G)))
            G = Gj;
        }
      if (G >= 0.01 && G <= 100.)
        return;
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cerr << "rollnip: warning: " << prefix
                  << "Material/C1 + C2: the shear modulus 2 (C1 + C2) = " << G
                  << " MPa is outside 0.01 to 100 MPa, the range of rubbers "
                     "(a unit mistake? C1 and C2 are in MPa)"
                  << std::endl;
    }

    std::string
    describe(const Parameters::AllParameters &p)
    {
      std::ostringstream s;
      s << std::setprecision(6);
      if (p.geometry.from_diameters)
        s << "Geometry: roll diameter " << 2 * p.geometry.outer_radius
          << " mm, cover thickness "
          << p.geometry.outer_radius - p.geometry.inner_radius
          << " mm: R0 = " << p.geometry.outer_radius
          << " mm, R1 = " << p.geometry.inner_radius << " mm\n";
      const RollDescription roll =
        describe_roll(p.geometry, p.mesh, p.material);
      if (roll.modulus_from_hardness())
        {
          const auto &layers = roll.layers;
          s << "Material: " << roll.hardness_source << ":";
          for (unsigned int j = 0; j < layers.size(); ++j)
            s << (j ? ";" : "")
              << (layers.size() > 1 ? " layer " + std::to_string(j + 1)
                                    : std::string())
              << " E = " << layers[j].youngs_modulus()
              << " MPa (an estimate from hardness), G = E/3 = "
              << layers[j].shear_modulus() << " MPa, C1 = " << layers[j].C1
              << " MPa, C2 = " << layers[j].C2 << " MPa";
          s << '\n';
        }
      const auto &c = p.contact;
      if (c.mode == Parameters::ContactMode::load && c.load_unit.name != "N/mm")
        {
          s << (c.load_unit.is_total_force() ? "Contact: total forces"
                                             : "Contact: line loads");
          for (unsigned int i = 0; i < c.values.size(); ++i)
            s << (i ? ", " : " ") << c.values[i] / c.load_unit.to_n_per_mm
              << ' ' << c.load_unit.name << " = " << c.values[i] << " N/mm";
          if (c.load_unit.is_total_force())
            s << " (over a face length of " << c.load_unit.face_length
              << " mm)";
          s << '\n';
        }
      return s.str();
    }

    std::string
    summary_entries(const Parameters::AllParameters &p)
    {
      const RollDescription roll =
        describe_roll(p.geometry, p.mesh, p.material);
      const LayerDescription &surface = roll.surface_layer();
      std::ostringstream      s;
      s << std::setprecision(8)
        << "shear_modulus_G_MPa = " << surface.shear_modulus() << '\n'
        << "youngs_modulus_E_MPa = " << surface.youngs_modulus() << '\n'
        << "modulus_source = "
        << (roll.modulus_from_hardness()
              ? "estimate from hardness " + roll.hardness_source
              : std::string("C1, C2"))
        << '\n'
        << "line_load_unit = " << p.contact.load_unit.name << '\n';
      if (p.contact.load_unit.is_total_force())
        s << "face_length_mm = " << p.contact.load_unit.face_length << '\n';
      return s.str();
    }
  } // namespace EngineeringInputs
} // namespace rollnip
