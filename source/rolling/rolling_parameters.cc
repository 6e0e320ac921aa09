#include <deal.II/base/numbers.h>

#include <rollnip/parameter_entries.h>
#include <rollnip/parameters.h>
#include <rollnip/rolling/rolling_parameters.h>

#include <algorithm>
#include <cmath>

namespace rollnip
{
  namespace Parameters
  {
    double
    ViscousLayer::viscous_time() const
    {
      double t = 0;
      for (unsigned int i = 0; i < g.size(); ++i)
        t += g[i] * tau[i];
      return t;
    }

    double
    ViscousLayer::longest_time() const
    {
      return tau.empty() ? 0. : *std::max_element(tau.begin(), tau.end());
    }

    double
    retardation_time_from_loss_tangent(const double tan_delta,
                                       const double frequency)
    {
      return tan_delta / (2. * numbers::PI * frequency);
    }

    namespace
    {
      /// The numbers of the comma-separated @p text; a word that is not a
      /// number is refused naming @p prefix @p entry (the subsection it is
      /// read in).
      std::vector<double>
      numbers_of(const std::string &text,
                 const std::string &entry,
                 const std::string &prefix = "Rolling/")
      {
        std::vector<double> v;
        for (const auto &word : Utilities::split_string_list(text, ','))
          {
            if (word.empty())
              continue;
            std::size_t end = 0;
            double      x   = std::nan("");
            try
              {
                x = std::stod(word, &end);
              }
            catch (...)
              {
                end = 0;
              }
            AssertThrow(end == word.size() && std::isfinite(x),
                        ExcMessage(prefix + entry + ": '" + word +
                                   "' is not a number"));
            v.push_back(x);
          }
        return v;
      }

      /// The per-layer groups of @p text, separated by ';' (one group: all
      /// layers).
      std::vector<std::vector<double>>
      layer_groups(const std::string &text,
                   const std::string &entry,
                   const std::string &prefix)
      {
        std::vector<std::vector<double>> groups;
        for (const auto &group : Utilities::split_string_list(text, ';'))
          groups.push_back(numbers_of(group, entry, prefix));
        return groups;
      }

      /// One value per layer (or one for all), each in (0, inf) unless
      /// @p zero_allowed; errors name @p prefix @p entry.
      std::vector<double>
      per_layer(const std::string &text,
                const std::string &entry,
                const unsigned int n_layers,
                const std::string &prefix,
                const bool         zero_allowed = false)
      {
        const auto v = numbers_of(text, entry, prefix);
        AssertThrow(v.size() == 1 || v.size() == n_layers,
                    ExcMessage(prefix + entry + " has " +
                               std::to_string(v.size()) +
                               " values: give one, or one per layer (" +
                               std::to_string(n_layers) + ")"));
        for (const double x : v)
          AssertThrow(zero_allowed ? x >= 0 : x > 0,
                      ExcMessage(prefix + entry + " must be " +
                                 (zero_allowed ? "non-negative" : "positive") +
                                 ", not " + number(x)));
        return v;
      }

      void
      declare_speed(ParameterHandler &prm)
      {
        declare_documented(prm,
                           "Enabled",
                           "false",
                           Patterns::Bool(),
                           "true: after each nip, the cover's hysteresis "
                           "loss in steady rolling (first order in the "
                           "speed), the rolling resistance, the drive power "
                           "and the cover's temperature (doc/rolling.md)");
        declare_documented(prm,
                           "Surface speed",
                           "0",
                           Patterns::Double(0.),
                           "Surface speed of the roll in Speed unit; 0: "
                           "Contact/Surface speed [m/min]");
        declare_documented(prm,
                           "Speed unit",
                           "m/min",
                           Patterns::Selection("m/min|m/s"),
                           "Unit of Surface speed and Speed table");
        declare_documented(prm,
                           "Speed table",
                           "",
                           Patterns::List(Patterns::Double(0.), 0),
                           "More speeds in Speed unit for the table of "
                           "rolling resistance and temperatures against "
                           "speed (rolling_speeds.csv); empty: none");
        declare_documented(prm,
                           "Full steady rolling",
                           "false",
                           Patterns::Bool(),
                           "true: also the full steady rolling of each nip "
                           "at its indentation, by continuation in speed "
                           "from the elastic nip, with the Prony terms of "
                           "the cover (rolling_full.csv, doc/rolling.md)");
        declare_documented(prm,
                           "Full rolling speeds",
                           "",
                           Patterns::List(Patterns::Double(0.), 0),
                           "Speeds of the full steady rolling in Speed "
                           "unit, ascending; empty: Surface speed and Speed "
                           "table");
        declare_documented(prm,
                           "Full rolling nip cells",
                           "100",
                           Patterns::Integer(4),
                           "Cells of the full steady rolling's mesh across "
                           "2.5 times the nip's half-angle on each side of "
                           "the line of centres");
        declare_documented(prm,
                           "Full rolling radial cells",
                           "16",
                           Patterns::Integer(1),
                           "Radial cells of the full steady rolling's mesh");
      }

      /// The cover's hysteresis entries (the roll's, the mating roll's).
      void
      declare_law(ParameterHandler &prm)
      {
        declare_documented(prm,
                           "Viscoelastic model",
                           "loss tangent",
                           Patterns::Selection(
                             "kelvin-voigt|prony|loss tangent"),
                           "kelvin-voigt: one retardation time per layer; "
                           "prony: relaxation moduli and times on the "
                           "isochoric part, relative to the long-term "
                           "modulus of Material; loss tangent: tan(delta) at "
                           "a frequency, fitted by one Kelvin-Voigt dashpot");
        declare_documented(prm,
                           "Retardation time",
                           "0.0002",
                           Patterns::Anything(),
                           "kelvin-voigt: tau [s], one value or one per "
                           "layer (comma-separated, from the core out)");
        declare_documented(prm,
                           "Relaxation moduli",
                           "0.2",
                           Patterns::Anything(),
                           "prony: g_i >= 0 over the long-term modulus, "
                           "comma-separated; layers separated by ';' (one "
                           "group: every layer)");
        declare_documented(prm,
                           "Relaxation times",
                           "0.001",
                           Patterns::Anything(),
                           "prony: tau_i > 0 [s], as many as Relaxation "
                           "moduli in each group");
        declare_documented(prm,
                           "Loss tangent",
                           "0.1",
                           Patterns::Anything(),
                           "loss tangent: tan(delta) > 0, one value or one "
                           "per layer");
        declare_documented(prm,
                           "Loss tangent frequency",
                           "100",
                           Patterns::Anything(),
                           "loss tangent: the frequency of the measurement "
                           "[Hz], one value or one per layer");
      }

      void
      declare_thermal(ParameterHandler &prm)
      {
        declare_documented(prm,
                           "Thermal conductivity",
                           "0.25",
                           Patterns::Anything(),
                           "Of the cover [W/(m K)], one value or one per "
                           "layer (rubber 0.15 to 0.4)");
        declare_documented(prm,
                           "Heat transfer coefficient",
                           "30",
                           Patterns::Double(0.),
                           "From the cover's surface to the air [W/(m^2 "
                           "K)] (a turning roll in still air about 10 to "
                           "50, with air jets or a cooled mating roll more)");
        declare_documented(prm,
                           "Ambient temperature",
                           "20",
                           Patterns::Double(-273.15),
                           "Of the air [degC]");
        declare_documented(prm,
                           "Core temperature",
                           "20",
                           Patterns::Double(-273.15),
                           "Of the core, Core thermal condition = fixed "
                           "temperature [degC]");
        declare_documented(prm,
                           "Core thermal condition",
                           "fixed temperature",
                           Patterns::Selection("fixed temperature|insulated"),
                           "fixed temperature: the core holds Core "
                           "temperature (a cooled or massive core); "
                           "insulated: no heat leaves through the core");
      }
    } // namespace

    void
    Rolling::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Rolling");
      declare_speed(prm);
      declare_law(prm);
      declare_thermal(prm);
      ThermalSoftening::declare(prm);
      prm.enter_subsection("Mating roll");
      declare_documented(prm,
                         "Hysteresis",
                         "as roll",
                         Patterns::Selection("as roll|own"),
                         "With Mating roll/Type = covered roll, the mating "
                         "roll's cover: as roll: the hysteresis and thermal "
                         "entries of Rolling; own: the entries of this "
                         "subsection");
      declare_law(prm);
      declare_thermal(prm);
      prm.leave_subsection();
      prm.leave_subsection();
    }

    namespace
    {
      /// The hysteresis of every layer from the entries of @p model;
      /// errors name the entries under @p prefix.
      std::vector<ViscousLayer>
      viscous_layers(ParameterHandler       &prm,
                     const ViscoelasticModel model,
                     const unsigned int      n_layers,
                     const std::string      &prefix)
      {
        std::vector<ViscousLayer> layers;
        if (model == ViscoelasticModel::prony)
          {
            const auto g   = layer_groups(prm.get("Relaxation moduli"),
                                        "Relaxation moduli",
                                        prefix);
            const auto tau = layer_groups(prm.get("Relaxation times"),
                                          "Relaxation times",
                                          prefix);
            AssertThrow(g.size() == tau.size() &&
                          (g.size() == 1 || g.size() == n_layers),
                        ExcMessage(prefix +
                                   "Relaxation moduli and Relaxation "
                                   "times need one group, or one per layer (" +
                                   std::to_string(n_layers) +
                                   "), separated by ';'"));
            for (unsigned int l = 0; l < g.size(); ++l)
              {
                AssertThrow(!g[l].empty() && g[l].size() == tau[l].size(),
                            ExcMessage(prefix +
                                       "Relaxation moduli and "
                                       "Relaxation times need as many values "
                                       "each (group " +
                                       std::to_string(l + 1) + ")"));
                for (unsigned int i = 0; i < g[l].size(); ++i)
                  AssertThrow(g[l][i] >= 0 && tau[l][i] > 0,
                              ExcMessage(prefix +
                                         "Relaxation moduli must be "
                                         ">= 0 and Relaxation times > 0 "
                                         "(group " +
                                         std::to_string(l + 1) + ")"));
                layers.push_back({g[l], tau[l]});
              }
            return layers;
          }
        std::vector<double> tau;
        if (model == ViscoelasticModel::kelvin_voigt)
          tau = per_layer(prm.get("Retardation time"),
                          "Retardation time",
                          n_layers,
                          prefix,
                          true);
        else
          {
            const auto tan_delta = per_layer(prm.get("Loss tangent"),
                                             "Loss tangent",
                                             n_layers,
                                             prefix);
            auto       f         = per_layer(prm.get("Loss tangent frequency"),
                               "Loss tangent frequency",
                               n_layers,
                               prefix);
            for (unsigned int l = 0; l < tan_delta.size(); ++l)
              tau.push_back(retardation_time_from_loss_tangent(
                tan_delta[l], f.size() == 1 ? f[0] : f[l]));
            if (f.size() > tau.size())
              tau.resize(f.size(), tau[0]);
          }
        for (const double t : tau)
          layers.push_back({{1.}, {t}});
        return layers;
      }
    } // namespace

    void
    Rolling::parse(ParameterHandler  &prm,
                   const unsigned int n_layers,
                   const double       contact_speed,
                   const unsigned int mate_layers)
    {
      prm.enter_subsection("Rolling");
      enabled             = prm.get_bool("Enabled");
      in_m_per_min        = prm.get("Speed unit") == "m/min";
      const double factor = in_m_per_min ? 1. / 60. : 1.;
      speed               = prm.get_double("Surface speed") * factor;
      if (speed == 0)
        speed = contact_speed / 60.;
      speeds = {speed};
      for (const double v : numbers_of(prm.get("Speed table"), "Speed table"))
        speeds.push_back(v * factor);
      full_steady = prm.get_bool("Full steady rolling");
      full_speeds.clear();
      for (const double v :
           numbers_of(prm.get("Full rolling speeds"), "Full rolling speeds"))
        full_speeds.push_back(v * factor);
      if (full_speeds.empty())
        {
          full_speeds = speeds;
          std::sort(full_speeds.begin(), full_speeds.end());
        }
      AssertThrow(std::is_sorted(full_speeds.begin(), full_speeds.end()),
                  ExcMessage("Rolling/Full rolling speeds: the speeds must "
                             "be ascending (a continuation in speed)"));
      full_nip_cells    = prm.get_integer("Full rolling nip cells");
      full_radial_cells = prm.get_integer("Full rolling radial cells");
      parse_cover(prm, n_layers);
      softening.parse(prm, n_layers);
      if (mate_layers > 0)
        parse_mate(prm, mate_layers);
      prm.leave_subsection();
    }

    namespace
    {
      /// The cover's hysteresis and thermal entries of the current
      /// subsection into @p r; errors name them under @p prefix.
      void
      parse_cover_entries(Rolling           &r,
                          ParameterHandler  &prm,
                          const unsigned int n_layers,
                          const std::string &prefix)
      {
        const std::string m = prm.get("Viscoelastic model");
        r.model             = m == "prony"          ? ViscoelasticModel::prony
                              : m == "kelvin-voigt" ? ViscoelasticModel::kelvin_voigt
                                                    : ViscoelasticModel::loss_tangent;
        r.layers            = viscous_layers(prm, r.model, n_layers, prefix);
        r.conductivity      = per_layer(prm.get("Thermal conductivity"),
                                   "Thermal conductivity",
                                   n_layers,
                                   prefix);
        r.heat_transfer     = prm.get_double("Heat transfer coefficient");
        r.ambient           = prm.get_double("Ambient temperature");
        r.core              = prm.get_double("Core temperature");
        r.core_condition    = prm.get("Core thermal condition") == "insulated"
                                ? CoreThermalCondition::insulated
                                : CoreThermalCondition::fixed_temperature;
      }
    } // namespace

    void
    Rolling::parse_cover(ParameterHandler &prm, const unsigned int n_layers)
    {
      parse_cover_entries(*this, prm, n_layers, "Rolling/");
    }

    void
    Rolling::parse_mate(ParameterHandler &prm, const unsigned int n_layers)
    {
      prm.enter_subsection("Mating roll");
      if (prm.get("Hysteresis") == "own")
        {
          mate = std::make_shared<Rolling>();
          parse_cover_entries(*mate, prm, n_layers, "Rolling/Mating roll/");
        }
      else
        {
          AssertThrow((layers.size() == 1 || layers.size() == n_layers) &&
                        (conductivity.size() == 1 ||
                         conductivity.size() == n_layers),
                      ExcMessage("Rolling/Mating roll/Hysteresis = as roll: "
                                 "the roll's per-layer values do not fit the "
                                 "mating roll's " +
                                 std::to_string(n_layers) +
                                 " layers; set Hysteresis = own"));
          mate = std::make_shared<Rolling>(*this);
        }
      mate->enabled = enabled;
      mate->speed   = speed;
      mate->speeds  = {speed};
      prm.leave_subsection();
    }

    void
    Rolling::validate(const AllParameters &scene) const
    {
      if (!enabled)
        return;
      AssertThrow(scene.contact.mode != ContactMode::none,
                  ExcMessage("Rolling/Enabled needs a nip: set Contact/Mode"));
      AssertThrow(!scene.mating_roll.covered ||
                    scene.mating_roll.mesh.source == MeshSource::builtin,
                  ExcMessage("Rolling/Enabled needs Mating roll/Mesh/Source "
                             "= builtin (the mating roll's loss is "
                             "integrated along its mesh's circles)"));
      AssertThrow(!mate || mate->heat_transfer > 0 ||
                    mate->core_condition ==
                      CoreThermalCondition::fixed_temperature,
                  ExcMessage("Rolling/Mating roll/Heat transfer coefficient "
                             "must be positive with Core thermal condition "
                             "= insulated (the heat would have no way "
                             "out)"));
      AssertThrow(scene.mesh.source == MeshSource::builtin,
                  ExcMessage("Rolling/Enabled needs Mesh/Source = builtin "
                             "(the loss is integrated along the mesh's "
                             "circles)"));
      AssertThrow(speed > 0,
                  ExcMessage("Rolling/Surface speed must be positive (or "
                             "Contact/Surface speed set) when "
                             "Rolling/Enabled = true"));
      AssertThrow(heat_transfer > 0 ||
                    core_condition == CoreThermalCondition::fixed_temperature,
                  ExcMessage("Rolling/Heat transfer coefficient must be "
                             "positive with Core thermal condition = "
                             "insulated (the heat would have no way out)"));
      AssertThrow(!full_steady || model == ViscoelasticModel::prony,
                  ExcMessage("Rolling/Full steady rolling needs "
                             "Rolling/Viscoelastic model = prony (a "
                             "Kelvin-Voigt dashpot or a loss tangent is not "
                             "a Maxwell branch)"));
      // The companions solve their nips at the constant modulus.
      AssertThrow(!softening.active() || (!scene.contact.compare_linear &&
                                          !scene.accuracy.error_estimate),
                  ExcMessage("Rolling/Temperature dependence needs "
                             "Contact/Compare with linear theory = false and "
                             "Accuracy/Error estimate = false"));
    }
  } // namespace Parameters
} // namespace rollnip
