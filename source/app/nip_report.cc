#include <deal.II/base/mpi.h>

#include <rollnip/app/nip_report.h>
#include <rollnip/output/atomic_file.h>

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
    /// One nip's numbers in the report's units, and their estimated
    /// errors (nan: none).
    struct ReportRow
    {
      double load_user, load, width, u0, peak, mean, dwell;
      double load_err, width_err, u0_err, peak_err, mean_err;
    };

    /// @p value (three decimals) with its estimated error @p error (two
    /// significant digits; skipped if nan) in a field of @p width
    /// characters.
    std::string
    with_error(const double value, const double error, const int width)
    {
      std::ostringstream s;
      s << std::fixed << std::setprecision(3) << value;
      if (!std::isnan(error))
        s << " +- " << std::defaultfloat << std::setprecision(2) << error;
      std::ostringstream field;
      field << std::setw(width) << s.str();
      return field.str();
    }

    ReportRow
    report_row(const NipRow &r, const Parameters::Contact &c)
    {
      const ContactResult &n = r.nonlinear;
      ReportRow            row;
      row.load      = n.nip_load;
      row.load_user = n.nip_load / c.load_unit.to_n_per_mm;
      row.width     = 2 * n.half_chord;
      row.u0        = n.indentation;
      row.peak      = n.peak_pressure;
      // P is the two-sided load: the mean over the full width 2b.
      row.mean = n.nip_load / row.width;
      row.dwell =
        c.surface_speed > 0 ? dwell_time_ms(row.width, c.surface_speed) : 0;
      const ErrorEstimate &e   = r.error;
      const double         nan = std::numeric_limits<double>::quiet_NaN();
      auto err = [&](const NipQuantity::Index q, const double factor = 1) {
        return e.available ? factor * e.error[q] : nan;
      };
      row.load_err  = err(NipQuantity::load);
      row.width_err = err(NipQuantity::half_chord, 2);
      row.u0_err    = err(NipQuantity::indentation);
      row.peak_err  = err(NipQuantity::peak_pressure);
      row.mean_err  = err(NipQuantity::mean_pressure);
      return row;
    }

    /// E of @p roll's surface layer and where it came from, as in the
    /// report's heading.
    std::string
    modulus_text(const RollDescription &roll)
    {
      std::ostringstream s;
      s << std::setprecision(4) << roll.surface_layer().youngs_modulus()
        << " MPa"
        << (roll.modulus_from_hardness()
              ? ", an estimate from hardness " + roll.hardness_source
              : ", from C1 and C2");
      return s.str();
    }

    void
    print_report(const std::vector<ReportRow> &rows,
                 const Parameters::Contact    &c,
                 const SceneDescription       &scene)
    {
      const bool dwell = c.surface_speed > 0;
      std::cout << std::endl
                << std::defaultfloat << std::setprecision(4)
                << "Nip report (E = " << modulus_text(scene.roll);
      if (dwell)
        std::cout << "; surface speed " << c.surface_speed << " m/min";
      if (const RollDescription *mate = scene.covered_mate())
        std::cout << "; mating roll E = " << modulus_text(*mate);
      if (c.load_unit.is_total_force())
        std::cout << "; total force on a face of " << c.load_unit.face_length
                  << " mm";
      std::cout << ")" << std::endl;
      // With error estimates each number is followed by +- its error.
      const bool errors = !rows.empty() && !std::isnan(rows[0].width_err);
      const int  w      = errors ? 10 : 0;
      std::cout << std::setw(16) << "load [" + c.load_unit.name + "]"
                << std::setw(15 + w) << "width 2b [mm]" << std::setw(9 + w)
                << "u0 [mm]" << std::setw(14 + w) << "peak p [MPa]"
                << std::setw(14 + w) << "mean p [MPa]"
                << (dwell ? "  dwell [ms]" : "") << std::endl;
      for (const auto &r : rows)
        {
          std::cout << std::fixed << std::setprecision(3) << std::setw(16)
                    << r.load_user << with_error(r.width, r.width_err, 15 + w)
                    << with_error(r.u0, r.u0_err, 9 + w)
                    << with_error(r.peak, r.peak_err, 14 + w)
                    << with_error(r.mean, r.mean_err, 14 + w);
          if (dwell)
            std::cout << std::setw(12) << r.dwell;
          std::cout << std::defaultfloat << std::endl;
        }
    }

    void
    write_report_csv(const std::vector<ReportRow> &rows,
                     const Parameters::Contact    &c,
                     const SceneDescription       &scene,
                     const std::string            &file)
    {
      const double E        = scene.roll.surface_layer().youngs_modulus();
      const bool   dwell    = c.surface_speed > 0;
      const bool   estimate = scene.roll.modulus_from_hardness();
      // A covered mating roll: its modulus beside the roll's.
      const RollDescription *mate      = scene.covered_mate();
      const bool             two_rolls = mate != nullptr;
      const double           E_mate =
        two_rolls ? mate->surface_layer().youngs_modulus() : 0;
      const bool mate_estimate = two_rolls && mate->modulus_from_hardness();
      write_atomically(file, [&](std::ostream &out) {
        out << "nip," << c.load_unit.column_name()
            << ",line_load_N_per_mm,nip_width_2b_mm,indentation_u0_mm,"
               "peak_pressure_MPa,mean_pressure_MPa,"
            << (dwell ? "surface_speed_m_per_min,dwell_time_ms," : "")
            << "youngs_modulus_E_MPa,E_estimated_from_hardness"
            << (two_rolls ? ",mating_roll_youngs_modulus_E_MPa,"
                            "mating_roll_E_estimated_from_hardness"
                          : "")
            << ",line_load_err_N_per_mm,nip_width_2b_err_mm,"
               "indentation_u0_err_mm,peak_pressure_err_MPa,"
               "mean_pressure_err_MPa\n"
            << std::setprecision(10);
        for (unsigned int i = 0; i < rows.size(); ++i)
          {
            const ReportRow &r = rows[i];
            out << i + 1 << ',' << r.load_user << ',' << r.load << ','
                << r.width << ',' << r.u0 << ',' << r.peak << ',' << r.mean
                << ',';
            if (dwell)
              out << c.surface_speed << ',' << r.dwell << ',';
            out << E << ',' << (estimate ? "yes" : "no");
            if (two_rolls)
              out << ',' << E_mate << ',' << (mate_estimate ? "yes" : "no");
            out << ',' << r.load_err << ',' << r.width_err << ',' << r.u0_err
                << ',' << r.peak_err << ',' << r.mean_err << '\n';
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
                   const bool                       print)
  {
    if (Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    std::vector<ReportRow> report;
    for (const auto &r : rows)
      report.push_back(report_row(r, parameters.contact));
    if (print)
      print_report(report, parameters.contact, scene);
    make_directories(top);
    write_report_csv(report,
                     parameters.contact,
                     scene,
                     top + "/nip_report.csv");
  }
} // namespace rollnip
