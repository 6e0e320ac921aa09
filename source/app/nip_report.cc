#include <deal.II/base/mpi.h>

#include <rollnip/app/nip_report.h>
#include <rollnip/contact/nip_estimates.h>
#include <rollnip/material/hardness.h>
#include <rollnip/output/atomic_file.h>
#include <rollnip/output/report_stream.h>
#include <rollnip/output/units.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace rollnip
{
  double
  dwell_time_ms(const double width, const double speed)
  {
    // v [m/min] = v / 60 [mm/ms].
    return width / (speed / 60.);
  }

  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /// The largest principal strain the Mooney-Rivlin (neo-Hookean) law
    /// is trusted to: Treloar's (1944) tension data leave the neo-Hookean
    /// curve beyond a stretch of about 1.5.
    constexpr double validated_strain = 0.5;
    /// The largest u0/h whose accuracy was measured, rounded up: the
    /// mesh study over u0 = 0.5 to 3 mm on a 13.5 mm cover
    /// (doc/accuracy.md) and Batra's (1980) 12 degree nip, u0/h = 0.224
    /// (doc/results.md).
    constexpr double validated_indentation_ratio = 0.23;
    /// The thin-layer asymptote applies from b/h = 4 (doc/results.md).
    constexpr double thin_layer_from_b_over_h = 4;

    /// One nip's numbers in the program's units (mm, MPa, N/mm, ms), and
    /// their estimated errors (nan: none) and the comparisons at its load.
    struct ReportRow
    {
      double         load, width, u0, peak, mean, dwell;
      double         load_err, width_err, u0_err, peak_err, mean_err;
      double         roll_u0 = nan, mate_u0 = nan; ///< two covered rolls
      double         hertz_width, hertz_peak, thin_width, thin_peak;
      BandWidths     band;
      RollingNumbers rolling; ///< the rolling loss, if asked
    };

    /// The comparisons of @p row at its load: Hertz always, the thin
    /// layer only where its own b/h reaches thin_layer_from_b_over_h.
    void
    add_comparisons(ReportRow &row, const SceneDescription &scene)
    {
      const double P   = row.load;
      const double b_h = NipEstimates::hertz_half_width(scene, P);
      row.hertz_width  = 2 * b_h;
      row.hertz_peak   = NipEstimates::hertz_peak_pressure(P, b_h);
      double h         = scene.roll.cover_thickness();
      if (const RollDescription *mate = scene.covered_mate())
        h = std::max(h, mate->cover_thickness());
      const double b_t  = NipEstimates::thin_layer_half_width(scene, P);
      const bool   thin = b_t / h >= thin_layer_from_b_over_h;
      row.thin_width    = thin ? 2 * b_t : nan;
      row.thin_peak =
        thin ? NipEstimates::thin_layer_peak_pressure(P, b_t) : nan;
    }

    ReportRow
    report_row(const NipRow &r, const Parameters::Contact &c)
    {
      const ContactResult &n = r.nonlinear;
      ReportRow            row;
      row.load  = n.nip_load;
      row.width = 2 * n.half_chord;
      row.u0    = n.indentation;
      row.peak  = n.peak_pressure;
      // P is the two-sided load: the mean over the full width 2b.
      row.mean = n.nip_load / row.width;
      row.dwell =
        c.surface_speed > 0 ? dwell_time_ms(row.width, c.surface_speed) : 0;
      if (n.two_rolls)
        {
          row.roll_u0 = n.roll_indentation;
          row.mate_u0 = n.mate_indentation;
        }
      const ErrorEstimate &e = r.error;
      auto err = [&](const NipQuantity::Index q, const double factor = 1) {
        return e.available ? factor * e.error[q] : nan;
      };
      row.load_err  = err(NipQuantity::load);
      row.width_err = err(NipQuantity::half_chord, 2);
      row.u0_err    = err(NipQuantity::indentation);
      row.peak_err  = err(NipQuantity::peak_pressure);
      row.mean_err  = err(NipQuantity::mean_pressure);
      row.rolling   = r.rolling;
      return row;
    }

    /// The units of the report: lengths, pressures, line loads, speeds.
    struct ReportUnits
    {
      Units::Unit length, pressure, line_load, speed;
      /// The loads' unit: Contact/Load unit in SI, pli in US (a total
      /// force stays as given).
      std::string load_name, load_column;
      double      load_per_n_per_mm;

      explicit ReportUnits(const Parameters::AllParameters &p)
      {
        using Units::Quantity;
        const auto system         = p.output.units;
        length                    = Units::unit(Quantity::length, system);
        pressure                  = Units::unit(Quantity::pressure, system);
        line_load                 = Units::unit(Quantity::line_load, system);
        speed                     = Units::unit(Quantity::speed, system);
        const LineLoadUnit &given = p.contact.load_unit;
        const bool          as_given =
          system == Parameters::UnitSystem::si || given.is_total_force();
        load_name   = as_given ? given.name : line_load.name;
        load_column = as_given ? given.column_name() : "line_load_pli";
        load_per_n_per_mm =
          as_given ? 1. / given.to_n_per_mm : line_load.per_program_unit;
      }
    };

    /// The decimals a number in @p unit is shown with: about the same
    /// resolution in both systems (0.001 mm or 0.0001 in, 0.001 MPa or
    /// 0.1 psi).
    int
    decimals(const Units::Unit &unit)
    {
      return unit.name == "in" ? 4 : unit.name == "psi" ? 1 : 3;
    }

    /// @p value in @p unit (from the program's) in a field of @p width.
    std::string
    field(const double value, const Units::Unit &unit, const int width)
    {
      std::ostringstream s;
      s << std::fixed << std::setprecision(decimals(unit)) << std::setw(width)
        << unit(value);
      return s.str();
    }

    /// @p value in @p unit with its estimated error @p error (two
    /// significant digits; skipped if nan), both from the program's
    /// unit, in a field of @p width characters.
    std::string
    with_error(const double       value,
               const double       error,
               const Units::Unit &unit,
               const int          width)
    {
      std::ostringstream s;
      s << std::fixed << std::setprecision(decimals(unit)) << unit(value);
      if (!std::isnan(error))
        s << " +- " << std::defaultfloat << std::setprecision(2) << unit(error);
      std::ostringstream field;
      field << std::setw(width) << s.str();
      return field.str();
    }

    /// E of @p roll's surface layer and where it came from, as in the
    /// report's heading.
    std::string
    modulus_text(const RollDescription &roll, const ReportUnits &u)
    {
      std::ostringstream s;
      s << std::setprecision(4)
        << u.pressure(roll.surface_layer().youngs_modulus()) << ' '
        << u.pressure.name
        << (roll.modulus_from_hardness()
              ? ", an estimate from hardness " + roll.hardness_source
              : ", from C1 and C2");
      return s.str();
    }
  } // namespace

  bool
  band_by_scaling(const Parameters::AllParameters &p)
  {
    return p.contact.mode == Parameters::ContactMode::load &&
           !p.mating_roll.covered && p.material.surface_hardness > 0 &&
           p.material.n_layers() == 1;
  }

  void
  warn_outside_validated_range(const NipRow           &row,
                               const unsigned int      n,
                               const SceneDescription &scene)
  {
    const double strain = row.max_principal_strain;
    if (strain > validated_strain)
      std::cerr << "rollnip: warning: nip " << n << ": the largest principal "
                << "strain " << std::setprecision(3) << 100 * strain
                << " % exceeds 50 %, beyond which the neo-Hookean law leaves "
                   "measured rubber (Treloar 1944) and a hardness modulus "
                   "(a small-strain modulus) no longer describes the cover"
                << std::endl;
    const double h  = scene.roll.cover_thickness();
    const double u0 = row.nonlinear.two_rolls ? row.nonlinear.roll_indentation
                                              : row.nonlinear.indentation;
    const double ratio = u0 / h;
    if (ratio > validated_indentation_ratio)
      std::cerr << "rollnip: warning: nip " << n << ": indentation/thickness "
                << "u0/h = " << std::setprecision(3) << ratio
                << " exceeds 0.23, beyond the nips whose accuracy was "
                   "measured (u0/h up to 0.224, doc/accuracy.md)"
                << std::endl;
  }

  namespace
  {
    void
    print_heading(const Parameters::AllParameters &p,
                  const SceneDescription          &scene,
                  const ReportUnits               &u)
    {
      const Parameters::Contact &c   = p.contact;
      std::ostream              &out = report_stream();
      out << std::endl
          << std::defaultfloat << std::setprecision(4)
          << "Nip report (E = " << modulus_text(scene.roll, u);
      if (c.surface_speed > 0)
        out << "; surface speed " << u.speed(c.surface_speed) << ' '
            << u.speed.name;
      if (const RollDescription *mate = scene.covered_mate())
        out << "; mating roll E = " << modulus_text(*mate, u);
      if (c.load_unit.is_total_force())
        out << "; total force on a face of "
            << u.length(c.load_unit.face_length) << ' ' << u.length.name;
      out << ")" << std::endl;
    }

    void
    print_report(const std::vector<ReportRow>    &rows,
                 const Parameters::AllParameters &p,
                 const SceneDescription          &scene,
                 const ReportUnits               &u)
    {
      print_heading(p, scene, u);
      std::ostream &out   = report_stream();
      const bool    dwell = p.contact.surface_speed > 0;
      const bool    two   = scene.covered_mate() != nullptr;
      // With error estimates each number is followed by +- its error.
      const bool errors   = !rows.empty() && !std::isnan(rows[0].width_err);
      const int  w        = errors ? 10 : 0;
      const std::string L = " [" + u.length.name + "]",
                        S = " [" + u.pressure.name + "]";
      out << std::setw(16) << "load [" + u.load_name + "]" << std::setw(15 + w)
          << "width 2b" + L << std::setw(9 + w) << "u0" + L << std::setw(14 + w)
          << "peak p" + S << std::setw(14 + w) << "mean p" + S
          << (dwell ? "  dwell [ms]" : "");
      if (two)
        out << std::setw(16) << "roll u0" + L << std::setw(16) << "mate u0" + L;
      out << std::endl;
      for (const auto &r : rows)
        {
          out << std::fixed << std::setprecision(3) << std::setw(16)
              << r.load * u.load_per_n_per_mm
              << with_error(r.width, r.width_err, u.length, 15 + w)
              << with_error(r.u0, r.u0_err, u.length, 9 + w)
              << with_error(r.peak, r.peak_err, u.pressure, 14 + w)
              << with_error(r.mean, r.mean_err, u.pressure, 14 + w);
          if (dwell)
            out << std::setw(12) << r.dwell;
          if (two)
            out << field(r.roll_u0, u.length, 16)
                << field(r.mate_u0, u.length, 16);
          out << std::defaultfloat << std::endl;
        }
    }

    /// The covered mating roll's own loss, if there is one.
    void
    print_mate_rolling(const std::vector<ReportRow> &rows)
    {
      if (!rows[0].rolling.mate.available)
        return;
      std::ostream &out = report_stream();
      out << "Mating roll's cover, same speed (first order):" << std::endl;
      for (const auto &r : rows)
        {
          const MateRolling &m = r.rolling.mate;
          out << std::setprecision(4) << std::setw(16) << m.rolling_resistance
              << std::setw(18) << m.power << std::fixed << std::setprecision(2)
              << std::setw(16) << m.bond_temperature << std::setw(18)
              << m.surface_temperature << std::setw(15) << m.max_temperature
              << std::defaultfloat << std::setprecision(3) << std::setw(12)
              << m.speed_over_nip << std::endl;
        }
    }

    /// The full steady rolling at the surface speed, if it ran there.
    void
    print_full_rolling(const std::vector<ReportRow> &rows)
    {
      if (!rows[0].rolling.full.available)
        return;
      std::ostream &out = report_stream();
      out << "Full steady rolling at " << std::setprecision(4)
          << rows[0].rolling.full.speed
          << " m/s (at the nip's approach; doc/rolling.md, section 7):"
          << std::endl
          << std::setw(16) << "F_r [N/mm]" << std::setw(18)
          << "drive power [W/m]" << std::setw(16) << "T bond [degC]"
          << std::setw(18) << "T surface [degC]" << std::setw(15)
          << "T max [degC]" << std::setw(12) << "P [N/mm]" << std::endl;
      for (const auto &r : rows)
        {
          // A nip whose full rolling did not converge there: nan.
          FullRolling f = r.rolling.full;
          if (!f.available)
            f.rolling_resistance = f.power = f.bond_temperature =
              f.surface_temperature = f.max_temperature = f.load = std::nan("");
          out << std::setprecision(4) << std::setw(16) << f.rolling_resistance
              << std::setw(18) << f.power << std::fixed << std::setprecision(2)
              << std::setw(16) << f.bond_temperature << std::setw(18)
              << f.surface_temperature << std::setw(15) << f.max_temperature
              << std::setw(12) << f.load << std::defaultfloat << std::endl;
        }
    }

    /// The fixed point of a cover that softens as it heats, if any: the
    /// constant-modulus nip beside the softened one.
    void
    print_softening(const std::vector<ReportRow> &rows)
    {
      if (!rows[0].rolling.thermal.active)
        return;
      std::ostream &out = report_stream();
      out << "Cover softened by its temperature (constant modulus -> fixed "
             "point):"
          << std::endl
          << std::setw(7) << "passes" << std::setw(13) << "contraction"
          << std::setw(22) << "2b [mm]" << std::setw(24) << "F_r [N/mm]"
          << std::setw(22) << "T max [degC]" << std::endl;
      for (const auto &r : rows)
        {
          const ThermalCoupling &t = r.rolling.thermal;
          auto pair = [](const double a, const double b, const int w) {
            std::ostringstream s;
            s << std::setprecision(5) << a << " -> " << b;
            std::ostringstream padded;
            padded << std::setw(w) << s.str();
            return padded.str();
          };
          out << std::setw(6) << t.iterations << (t.converged ? ' ' : '!')
              << std::setw(13) << std::setprecision(3) << t.contraction
              << pair(t.constant_width, t.width, 22)
              << pair(t.constant_rolling_resistance,
                      r.rolling.rolling_resistance,
                      24)
              << pair(t.constant_max, r.rolling.max_temperature, 22)
              << std::endl;
        }
    }

    /// The rolling columns of the report (doc/rolling.md), if computed;
    /// in SI units whatever Output/Units says.
    void
    print_rolling(const std::vector<ReportRow> &rows)
    {
      if (rows.empty() || !rows[0].rolling.available)
        return;
      std::ostream &out = report_stream();
      out << "Rolling at " << std::setprecision(4) << rows[0].rolling.speed
          << " m/s (first order in V tau / b):" << std::endl
          << std::setw(16) << "F_r [N/mm]" << std::setw(18)
          << "drive power [W/m]" << std::setw(16) << "T bond [degC]"
          << std::setw(18) << "T surface [degC]" << std::setw(15)
          << "T max [degC]" << std::setw(12) << "V tau / b" << std::endl;
      for (const auto &r : rows)
        out << std::setprecision(4) << std::setw(16)
            << r.rolling.rolling_resistance << std::setw(18) << r.rolling.power
            << std::fixed << std::setprecision(2) << std::setw(16)
            << r.rolling.bond_temperature << std::setw(18)
            << r.rolling.surface_temperature << std::setw(15)
            << r.rolling.max_temperature << std::defaultfloat
            << std::setprecision(3) << std::setw(12) << r.rolling.speed_over_nip
            << std::endl;
      print_mate_rolling(rows);
      print_softening(rows);
      print_full_rolling(rows);
    }

    /// The comparisons at each load, and the widths at the ends of the
    /// modulus band when they were solved.
    void
    print_comparisons(const std::vector<ReportRow>    &rows,
                      const Parameters::AllParameters &p,
                      const ReportUnits               &u)
    {
      std::ostream &out = report_stream();
      const bool    band =
        !rows.empty() && !std::isnan(rows[0].band.at_low_modulus);
      const std::string L = " [" + u.length.name + "]",
                        S = " [" + u.pressure.name + "]";
      out << "At the same load: Hertz (rigid cylinder on an incompressible "
             "half-space) and the thin bonded layer (nan: b/h below 4, where "
             "it does not apply)";
      if (band)
        {
          const Hardness::Band e =
            Hardness::modulus_band(p.material.surface_hardness,
                                   Hardness::scale_from_string(
                                     p.material.hardness_scale));
          out << "; 2b at the ends of the hardness modulus band E = "
              << std::setprecision(4) << u.pressure(e.low) << " to "
              << u.pressure(e.high) << ' ' << u.pressure.name;
        }
      out << std::endl
          << std::setw(16) << "load [" + u.load_name + "]" << std::setw(15)
          << "2b FE" + L << std::setw(15) << "2b Hertz" + L << std::setw(17)
          << "peak Hertz" + S << std::setw(15) << "2b thin" + L << std::setw(16)
          << "peak thin" + S;
      if (band)
        out << std::setw(18) << "2b at E_high" + L << std::setw(17)
            << "2b at E_low" + L;
      out << std::endl;
      for (const auto &r : rows)
        {
          out << std::fixed << std::setprecision(3) << std::setw(16)
              << r.load * u.load_per_n_per_mm << field(r.width, u.length, 15)
              << field(r.hertz_width, u.length, 15)
              << field(r.hertz_peak, u.pressure, 17)
              << field(r.thin_width, u.length, 15)
              << field(r.thin_peak, u.pressure, 16);
          if (band)
            out << field(r.band.at_high_modulus, u.length, 18)
                << field(r.band.at_low_modulus, u.length, 17);
          out << std::defaultfloat << std::endl;
        }
    }
  } // namespace

  namespace
  {
    /// The CSV header: the SI names are those of the earlier reports; the
    /// additions follow the estimated errors.
    std::string
    csv_header(const Parameters::AllParameters &p,
               const SceneDescription          &scene,
               const ReportUnits               &u,
               const bool                       rolling)
    {
      const std::string L = "_" + u.length.column, S = "_" + u.pressure.column,
                        F = "_" + u.line_load.column;
      std::ostringstream h;
      h << "nip," << u.load_column << ",line_load" << F << ",nip_width_2b" << L
        << ",indentation_u0" << L << ",peak_pressure" << S << ",mean_pressure"
        << S << ','
        << (p.contact.surface_speed > 0
              ? "surface_speed_" + u.speed.column + ",dwell_time_ms,"
              : "")
        << "youngs_modulus_E" << S << ",E_estimated_from_hardness"
        << (scene.covered_mate() ? ",mating_roll_youngs_modulus_E" + S +
                                     ",mating_roll_E_estimated_from_hardness"
                                 : "")
        << ",line_load_err" << F << ",nip_width_2b_err" << L
        << ",indentation_u0_err" << L << ",peak_pressure_err" << S
        << ",mean_pressure_err" << S;
      if (scene.covered_mate())
        h << ",roll_indentation" << L << ",mating_roll_indentation" << L;
      h << ",nip_width_2b_hertz" << L << ",peak_pressure_hertz" << S
        << ",nip_width_2b_thin_layer" << L << ",peak_pressure_thin_layer" << S
        << ",youngs_modulus_E_band_low" << S << ",youngs_modulus_E_band_high"
        << S << ",nip_width_2b_at_E_band_low" << L
        << ",nip_width_2b_at_E_band_high" << L;
      if (rolling)
        h << ",rolling_speed_m_per_s,rolling_resistance_N_per_mm,"
             "drive_power_W_per_m,heat_W_per_m,bond_temperature_degC,"
             "surface_temperature_degC,max_temperature_degC";
      return h.str();
    }

    void
    write_report_csv(const std::vector<ReportRow>    &rows,
                     const Parameters::AllParameters &p,
                     const SceneDescription          &scene,
                     const ReportUnits               &u,
                     const std::string               &file)
    {
      const Parameters::Contact &c = p.contact;
      const double           E = scene.roll.surface_layer().youngs_modulus();
      const bool             estimate = scene.roll.modulus_from_hardness();
      const RollDescription *mate     = scene.covered_mate();
      Hardness::Band         band{nan, nan};
      if (p.material.surface_hardness > 0)
        band = Hardness::modulus_band(p.material.surface_hardness,
                                      Hardness::scale_from_string(
                                        p.material.hardness_scale));
      write_atomically(file, [&](std::ostream &out) {
        const bool rolling = !rows.empty() && rows[0].rolling.available;
        out << csv_header(p, scene, u, rolling) << '\n'
            << std::setprecision(10);
        for (unsigned int i = 0; i < rows.size(); ++i)
          {
            const ReportRow &r = rows[i];
            out << i + 1 << ',' << r.load * u.load_per_n_per_mm << ','
                << u.line_load(r.load) << ',' << u.length(r.width) << ','
                << u.length(r.u0) << ',' << u.pressure(r.peak) << ','
                << u.pressure(r.mean) << ',';
            if (c.surface_speed > 0)
              out << u.speed(c.surface_speed) << ',' << r.dwell << ',';
            out << u.pressure(E) << ',' << (estimate ? "yes" : "no");
            if (mate)
              out << ',' << u.pressure(mate->surface_layer().youngs_modulus())
                  << ',' << (mate->modulus_from_hardness() ? "yes" : "no");
            out << ',' << u.line_load(r.load_err) << ','
                << u.length(r.width_err) << ',' << u.length(r.u0_err) << ','
                << u.pressure(r.peak_err) << ',' << u.pressure(r.mean_err);
            if (mate)
              out << ',' << u.length(r.roll_u0) << ',' << u.length(r.mate_u0);
            out << ',' << u.length(r.hertz_width) << ','
                << u.pressure(r.hertz_peak) << ',' << u.length(r.thin_width)
                << ',' << u.pressure(r.thin_peak) << ',' << u.pressure(band.low)
                << ',' << u.pressure(band.high) << ','
                << u.length(r.band.at_low_modulus) << ','
                << u.length(r.band.at_high_modulus);
            const RollingNumbers &n = r.rolling;
            if (rolling)
              out << ',' << n.speed << ',' << n.rolling_resistance << ','
                  << n.power << ',' << n.power << ',' << n.bond_temperature
                  << ',' << n.surface_temperature << ',' << n.max_temperature;
            out << '\n';
          }
      });
    }
  } // namespace

  void
  write_nip_report(const std::vector<NipRow>       &rows,
                   const Parameters::AllParameters &parameters,
                   const SceneDescription          &scene,
                   const std::string               &top,
                   const MPI_Comm                   communicator,
                   const std::vector<BandWidths>   &band,
                   const bool                       print)
  {
    if (Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    const ReportUnits      units(parameters);
    std::vector<ReportRow> report;
    for (unsigned int i = 0; i < rows.size(); ++i)
      {
        ReportRow row = report_row(rows[i], parameters.contact);
        add_comparisons(row, scene);
        if (i < band.size())
          row.band = band[i];
        report.push_back(row);
      }
    if (print)
      {
        print_report(report, parameters, scene, units);
        print_comparisons(report, parameters, units);
        print_rolling(report);
      }
    make_directories(top);
    write_report_csv(report, parameters, scene, units, top + "/nip_report.csv");
  }
} // namespace rollnip
