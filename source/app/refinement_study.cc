#include <deal.II/base/convergence_table.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <rollnip/app/adaptive_grading.h>
#include <rollnip/app/nip_study.h>
#include <rollnip/app/refinement_study.h>
#include <rollnip/boundary_ids.h>
#include <rollnip/geometry/roll_mesh.h>
#include <rollnip/output/atomic_file.h>
#include <rollnip/parameter_entries.h>
#include <rollnip/problem.h>
#include <rollnip/run_errors.h>
#include <rollnip/scene/scene_builder.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace rollnip
{
  Extrapolation
  extrapolate(const std::vector<double> &v, const double max_order)
  {
    Extrapolation e;
    if (v.empty())
      return e;
    e.value             = v.back();
    const std::size_t n = v.size();
    if (n < 3)
      return e;
    const double d1 = v[n - 2] - v[n - 3], d2 = v[n - 1] - v[n - 2];
    if (d1 == 0 || d2 == 0)
      return e;
    double r = d2 / d1;
    // Oscillating, or so slow (order < 0.15) that the estimate would rest
    // on noise.
    if (r <= 0 || r >= 0.9)
      return e;
    e.order = -std::log2(r);
    if (e.order > max_order)
      {
        e.capped = true;
        r        = std::pow(2., -max_order);
      }
    e.value = v[n - 1] + d2 * r / (1 - r);
    e.valid = true;
    return e;
  }

  namespace Parameters
  {
    void
    StudyValues::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Study");
      declare_documented(prm,
                         "Values",
                         "all",
                         Patterns::Anything(),
                         "The nips of a contact sweep the study runs: all "
                         "(every value of Contact/Values), or a list of "
                         "values in the unit of Contact/Values (theta0 "
                         "[deg], the line load in Contact/Load unit, or u0 "
                         "[mm]), e.g. 60");
      prm.leave_subsection();
    }

    void
    StudyValues::parse(ParameterHandler &prm, const AllParameters &scene)
    {
      prm.enter_subsection("Study");
      const std::string text = prm.get("Values");
      prm.leave_subsection();
      values.clear();
      const auto items = Utilities::split_string_list(text);
      if (items.empty() || (items.size() == 1 && items[0] == "all"))
        return;
      const auto &contact = scene.contact;
      AssertThrow(contact.mode != ContactMode::none,
                  ExcMessage("Study/Values names nips of a contact sweep: it "
                             "needs Contact/Mode = nip angle, load or "
                             "indentation"));
      AssertThrow(!scene.study.levels.empty(),
                  ExcMessage("Study/Values is set but Study/Refinement "
                             "levels is empty: there is no study to run"));
      const double scale =
        contact.mode == ContactMode::nip_angle ? numbers::PI / 180.
        : contact.mode == ContactMode::load    ? contact.load_unit.to_n_per_mm
                                               : 1.;
      for (const auto &item : items)
        {
          char        *end = nullptr;
          const double x   = std::strtod(item.c_str(), &end);
          AssertThrow(end != item.c_str() && *end == '\0' && std::isfinite(x) &&
                        x > 0,
                      ExcMessage("Study/Values: '" + item +
                                 "' is not a positive number (give 'all' or "
                                 "values in the unit of Contact/Values)"));
          values.push_back(x * scale);
        }
    }
  } // namespace Parameters

  namespace
  {
    struct Quantity
    {
      std::string label; ///< table column
      std::string key;   ///< CSV column
      std::string error; ///< table column of its error
    };

    const std::vector<Quantity> contact_quantities = {
      {"P [N/mm]", "P_N_per_mm", "e_P"},
      {"u0 [mm]", "u0_mm", "e_u0"},
      {"b [mm]", "half_chord_mm", "e_b"},
      {"peak f [MPa]", "peak_pressure_MPa", "e_peak"},
      {"bond s_rr [MPa]", "bond_sigma_rr_min_MPa", "e_srr"},
      {"bond s_rt [MPa]", "bond_sigma_rtheta_max_MPa", "e_srt"}};

    const std::vector<Quantity> pressure_quantities = {
      {"u0 [mm]", "u0_mm", "e_u0"},
      {"max strain", "max_principal_strain", "e_strain"},
      {"bond s_rr [MPa]", "bond_sigma_rr_min_MPa", "e_srr"},
      {"bond s_rt [MPa]", "bond_sigma_rtheta_max_MPa", "e_srt"}};

    /// One sequence of levels: an element, a sector angle, a step count.
    struct Variant
    {
      Parameters::Element element;
      double              sector_angle;  ///< [rad]
      unsigned int        initial_steps; ///< Load stepping/Initial steps
      std::string         label;         ///< for tables
      std::string         tag;           ///< for CSV and directories
    };

    /// One nip of the sweep the study runs (a pressure scene: one, with
    /// empty texts).
    struct StudiedNip
    {
      double      value = 0;   ///< Contact/Values entry [rad, N/mm or mm]
      std::string label;       ///< "P = 40 kN/m", for the screen
      std::string directory;   ///< "nip-02/" below study/ for several nips
      std::string csv_columns; ///< "2,40" before each row of study.csv
    };

    struct Run
    {
      unsigned int             nip     = 0;
      unsigned int             variant = 0;
      unsigned int             level   = 0;
      types::global_cell_index cells   = 0;
      types::global_dof_index  dofs    = 0;
      double                   wall    = 0; ///< [s]
      double                   memory  = 0; ///< peak resident set [MB]
      std::vector<double>      values;
    };

    std::string
    element_name(const Parameters::Element e)
    {
      return e == Parameters::Element::q2_p1 ? "Q2-P1" : "Q1-P0";
    }

    /// One run of the scene; returns the exit code.
    int
    run_scene(const Parameters::AllParameters &given,
              Run                             &run,
              const MPI_Comm                   communicator)
    {
      const Parameters::AllParameters p = adapt_grading(given, communicator);
      if (p.contact.mode != Parameters::ContactMode::none)
        {
          std::vector<NipRow> rows;
          const int           code = run_nip_study(p, communicator, &rows);
          if (code != 0 || rows.empty())
            return code != 0 ? code : 1;
          const NipRow &r = rows[0];
          run.cells       = r.n_cells;
          run.dofs        = r.n_dofs;
          run.values      = {r.nonlinear.nip_load,
                             r.nonlinear.indentation,
                             r.nonlinear.half_chord,
                             r.nonlinear.peak_pressure,
                             r.bond_sigma_rr_min,
                             r.bond_sigma_rtheta_max};
          return 0;
        }
      // Destroyed inside the handler when something throws, so that its
      // timer does not report on an exception in flight.
      auto scene = std::make_unique<Scene>(p, communicator);
      try
        {
          RollProblem    &problem = scene->roll();
          const RunStatus status  = problem.run();
          problem.write_results(status);
          if (!status.converged)
            {
              problem.silence_timer();
              return 1;
            }
          const SurfaceData  data = problem.surface_data(1.);
          const BondExtremes bond = bond_extremes(data.bond);
          run.cells               = problem.n_cells();
          run.dofs                = problem.n_dofs();
          run.values              = {-problem.radial_displacement_at(
                          Point<dim>(p.geometry.outer_radius, 0.)),
                                     data.extremes.max_principal_stretch - 1,
                                     bond.sigma_rr_min,
                                     bond.sigma_rtheta_max_abs};
        }
      catch (...)
        {
          scene->silence_timers();
          scene.reset();
          throw;
        }
      return 0;
    }

    /// The coarsest run whose estimated relative error in quantity q is
    /// below @p tolerance, as text.
    std::string
    cheapest(const std::vector<Run>    &runs,
             const std::vector<double> &exact,
             const unsigned int         q,
             const double               tolerance)
    {
      for (const auto &r : runs)
        if (std::abs(r.values[q] / exact[q] - 1) < tolerance)
          {
            std::ostringstream s;
            s << "level " << r.level << " (" << r.dofs << " DoFs, "
              << std::setprecision(3) << r.wall << " s)";
            return s.str();
          }
      return "none of the levels run";
    }
  } // namespace

  namespace
  {
    /// Elements x sector angles x initial steps, in the order listed.
    std::vector<Variant>
    make_variants(const Parameters::AllParameters &parameters)
    {
      const auto &study    = parameters.study;
      auto        elements = study.elements;
      if (elements.empty())
        elements = {parameters.discretization.element};
      auto angles = study.sector_angles;
      if (angles.empty())
        angles = {parameters.geometry.sector_angle};
      auto steps = study.initial_steps;
      if (steps.empty())
        steps = {parameters.load_stepping.n_initial_steps};
      std::vector<Variant> variants;
      for (const auto e : elements)
        for (const double a : angles)
          for (const unsigned int n : steps)
            {
              Variant            v{e, a, n, element_name(e), element_name(e)};
              std::ostringstream deg;
              deg << std::setprecision(6) << a / (numbers::PI / 180.);
              if (!study.sector_angles.empty())
                {
                  v.label += ", sector " + deg.str() + " deg";
                  v.tag += "-sector-" + deg.str();
                }
              if (!study.initial_steps.empty())
                {
                  v.label += ", " + std::to_string(n) + " initial load steps";
                  v.tag += "-steps-" + std::to_string(n);
                }
              variants.push_back(v);
            }
      return variants;
    }

    /// @p p on the sector @p angle instead of that of @p given.
    void
    set_sector(const Parameters::AllParameters &given,
               const double                     angle,
               Parameters::AllParameters       &p)
    {
      // The same coarse cells near the nip on every sector: cells are
      // added or dropped at the far end.
      p.geometry.sector_angle = angle;
      p.mesh.circumferential_steps =
        extend_steps(coarse_circumferential_steps(given), angle);
      // The nip-fitted mesh: the same nip cells, the cells beyond them in
      // proportion to the sector.
      const unsigned int n_far =
        given.mesh.circumferential_cells - given.mesh.nip_cells;
      p.mesh.circumferential_cells =
        given.mesh.nip_cells +
        std::max(2u,
                 static_cast<unsigned int>(
                   std::lround(n_far * angle / given.geometry.sector_angle)));
      auto &far = p.boundary_conditions.condition[BoundaryIds::far_edge];
      if (angle > numbers::PI - 1e-9)
        far = Parameters::BoundaryCondition::symmetry;
      else if (given.geometry.sector_angle > numbers::PI - 1e-9 &&
               far == Parameters::BoundaryCondition::symmetry)
        far = Parameters::BoundaryCondition::free; // truncated
    }

    /// The parameters of one run: @p variant of the study's scene at
    /// refinement @p level, with its files below the study's directory.
    Parameters::AllParameters
    run_parameters(const Parameters::AllParameters &parameters,
                   const StudiedNip                &nip,
                   const Variant                   &variant,
                   const unsigned int               level)
    {
      Parameters::AllParameters p     = parameters;
      p.mesh.global_refinements       = level;
      p.discretization.element        = variant.element;
      p.load_stepping.n_initial_steps = variant.initial_steps;
      if (variant.sector_angle != parameters.geometry.sector_angle)
        set_sector(parameters, variant.sector_angle, p);
      p.output.print_timing    = false;
      p.contact.compare_linear = false;
      // The study measures the error itself, from all its levels.
      p.accuracy.error_estimate = false;
      p.output.directory        = parameters.output.directory + "/study/" +
                           nip.directory + variant.tag + "-level-" +
                           std::to_string(level);
      if (p.contact.mode != Parameters::ContactMode::none)
        p.contact.values = {nip.value};
      return p;
    }

    /// Runs the scene @p p into @p run, with its wall time (the slowest
    /// process) and memory (all processes); returns the exit code, and in
    /// @p thrown what a failed run threw.
    int
    timed_run(const Parameters::AllParameters &p,
              Run                             &run,
              std::string                     &thrown,
              const MPI_Comm                   communicator)
    {
      const auto start = std::chrono::steady_clock::now();
      int        code  = 0;
      try
        {
          code = run_scene(p, run, communicator);
        }
      catch (const std::exception &e)
        {
          // Another process may be waiting in a collective call.
          rethrow_if_local(e);
          code   = 1;
          thrown = e.what();
        }
      run.wall = Utilities::MPI::max(std::chrono::duration<double>(
                                       std::chrono::steady_clock::now() - start)
                                       .count(),
                                     communicator);
      Utilities::System::MemoryStats memory;
      Utilities::System::get_memory_stats(memory);
      run.memory = Utilities::MPI::sum(memory.VmHWM / 1024., communicator);
      return code;
    }

    /// Every nip, variant and level, in order, into @p runs, each said on
    /// the screen; returns why the study stopped early, empty if it did
    /// not.
    std::string
    run_all(const Parameters::AllParameters &parameters,
            const std::vector<StudiedNip>   &nips,
            const std::vector<Variant>      &variants,
            std::vector<Run>                &runs,
            const MPI_Comm                   communicator)
    {
      ConditionalOStream pcout(std::cout,
                               Utilities::MPI::this_mpi_process(communicator) ==
                                 0);
      for (unsigned int k = 0; k < nips.size(); ++k)
        for (unsigned int vi = 0; vi < variants.size(); ++vi)
          for (const unsigned int level : parameters.study.levels)
            {
              const Variant                  &variant = variants[vi];
              const Parameters::AllParameters p =
                run_parameters(parameters, nips[k], variant, level);
              const std::string where =
                (nips[k].label.empty()
                   ? std::string()
                   : "nip " + std::to_string(k + 1) + " of " +
                       std::to_string(nips.size()) + ", " + nips[k].label +
                       ", ") +
                variant.label + ", level " + std::to_string(level);
              pcout << "Study: " << where << std::endl;
              Run         run;
              std::string thrown;
              const int   code = timed_run(p, run, thrown, communicator);
              run.nip          = k;
              run.variant      = vi;
              run.level        = level;
              if (code != 0)
                return where +
                       (thrown.empty() ? ": did not converge"
                                       : ": failed: " + thrown) +
                       " (see " + p.output.directory + ")";
              runs.push_back(run);
            }
      return "";
    }

    /// The header line of study.csv; leaves @p csv at the precision of its
    /// rows.
    void
    write_csv_header(const std::string           &nip_columns,
                     const std::vector<Quantity> &quantities,
                     std::ostringstream          &csv)
    {
      csv << nip_columns
          << "variant,element,sector_deg,initial_steps,level,cells,dofs";
      for (const auto &q : quantities)
        csv << ',' << q.key;
      for (const auto &q : quantities)
        csv << ",error_" << q.key;
      csv << ",wall_s,process_peak_memory_MB\n" << std::setprecision(10);
    }

    /// The extrapolated limit of each quantity over the levels @p mine of
    /// one variant of @p element.
    std::vector<Extrapolation>
    extrapolate_quantities(const std::vector<Run>   &mine,
                           const unsigned int        n_quantities,
                           const Parameters::Element element)
    {
      std::vector<Extrapolation> ex(n_quantities);
      for (unsigned int q = 0; q < n_quantities; ++q)
        {
          std::vector<double> v;
          for (const auto &r : mine)
            v.push_back(r.values[q]);
          // No element converges faster than its degree + 1 here.
          ex[q] =
            extrapolate(v, element == Parameters::Element::q2_p1 ? 3. : 2.);
        }
      return ex;
    }

    /// The table of the levels @p mine of @p variant with their errors
    /// against @p exact; their rows of study.csv go to @p csv.
    ConvergenceTable
    variant_table(const StudiedNip                 &nip,
                  const Variant                    &variant,
                  const std::vector<Run>           &mine,
                  const std::vector<double>        &exact,
                  const std::vector<Extrapolation> &ex,
                  const std::vector<Quantity>      &quantities,
                  std::ostringstream               &csv)
    {
      ConvergenceTable table;
      for (const auto &r : mine)
        {
          table.add_value("level", r.level);
          table.add_value("cells", static_cast<unsigned int>(r.cells));
          table.add_value("DoFs", static_cast<unsigned int>(r.dofs));
          csv << nip.csv_columns << variant.tag << ','
              << element_name(variant.element) << ','
              << variant.sector_angle / (numbers::PI / 180.) << ','
              << variant.initial_steps << ',' << r.level << ',' << r.cells
              << ',' << r.dofs;
          for (unsigned int q = 0; q < quantities.size(); ++q)
            {
              table.add_value(quantities[q].label, r.values[q]);
              csv << ',' << r.values[q];
            }
          for (unsigned int q = 0; q < quantities.size(); ++q)
            {
              const double e = exact[q] != 0
                                 ? std::abs(r.values[q] / exact[q] - 1)
                                 : std::abs(r.values[q]);
              table.add_value(quantities[q].error, e);
              csv << ',' << e;
            }
          table.add_value("wall [s]", r.wall);
          table.add_value("process peak [MB]", r.memory);
          csv << ',' << r.wall << ',' << r.memory << '\n';
        }
      for (unsigned int q = 0; q < quantities.size(); ++q)
        {
          const std::string l = quantities[q].label;
          table.set_precision(l, 6);
          const std::string &e = quantities[q].error;
          table.set_precision(e, 2);
          table.set_scientific(e, true);
          if (ex[q].valid)
            table.evaluate_convergence_rates(
              e, ConvergenceTable::reduction_rate_log2);
        }
      table.set_precision("wall [s]", 3);
      table.set_precision("process peak [MB]", 1);
      return table;
    }

    /// The extrapolated values of @p ex and their observed orders.
    void
    write_extrapolated(const std::vector<Extrapolation> &ex,
                       const std::vector<Quantity>      &quantities,
                       std::ostringstream               &text)
    {
      text << "Extrapolated values (observed order from the last three "
              "levels):\n";
      for (unsigned int q = 0; q < quantities.size(); ++q)
        {
          text << "  " << std::setw(16) << std::left << quantities[q].label
               << std::right << std::setprecision(8) << ex[q].value;
          if (ex[q].valid)
            text << "   order " << std::setprecision(3) << ex[q].order
                 << (ex[q].capped ? " (above element degree + 1: "
                                    "extrapolated with that order)"
                                  : "");
          else
            text << "   (not extrapolated: fewer than 3 levels or not "
                    "monotone; errors are against the finest level)";
          text << '\n';
        }
    }

    /// The study of variant @p vi: its table and limits to @p text, its
    /// rows to @p csv; returns its limits, empty if no level ran.
    std::vector<double>
    report_variant(const StudiedNip            &nip,
                   const unsigned int           k,
                   const Variant               &variant,
                   const unsigned int           vi,
                   const std::vector<Run>      &runs,
                   const std::vector<Quantity> &quantities,
                   const bool                   contact,
                   std::ostringstream          &text,
                   std::ostringstream          &csv)
    {
      std::vector<Run> mine;
      for (const auto &r : runs)
        if (r.nip == k && r.variant == vi)
          mine.push_back(r);
      if (mine.empty())
        return {};
      const std::vector<Extrapolation> ex =
        extrapolate_quantities(mine, quantities.size(), variant.element);
      std::vector<double> exact(quantities.size());
      for (unsigned int q = 0; q < quantities.size(); ++q)
        exact[q] = ex[q].value;
      ConvergenceTable table =
        variant_table(nip, variant, mine, exact, ex, quantities, csv);

      text << "Refinement study, "
           << (nip.label.empty()
                 ? std::string()
                 : "nip " + std::to_string(k + 1) + " (" + nip.label + "), ")
           << variant.label
           << " (e = relative error against the Richardson-extrapolated "
              "value; rates are log2 of the error reduction per level; "
              "process peak = the largest resident memory of the process "
              "so far, so it measures the largest run up to that row)\n";
      table.write_text(text, TableHandler::org_mode_table);
      write_extrapolated(ex, quantities, text);
      text << "Coarsest level within 1 % / 0.1 % of the extrapolated "
           << quantities[0].label << ": " << cheapest(mine, exact, 0, 1e-2)
           << " / " << cheapest(mine, exact, 0, 1e-3) << '\n';
      if (contact)
        text << "Coarsest level within 1 % / 0.1 % of the extrapolated "
                "nip half-width b: "
             << cheapest(mine, exact, 2, 1e-2) << " / "
             << cheapest(mine, exact, 2, 1e-3) << '\n';
      text << '\n';
      return exact;
    }

    /// The most faithful variant with limits of the element of variant
    /// @p vi: largest sector, then most initial load steps.
    unsigned int
    most_faithful(const std::vector<Variant>             &variants,
                  const std::vector<std::vector<double>> &limits,
                  const unsigned int                      vi)
    {
      unsigned int ref = vi;
      for (unsigned int k = 0; k < variants.size(); ++k)
        if (!limits[k].empty() && variants[k].element == variants[vi].element &&
            (variants[k].sector_angle > variants[ref].sector_angle ||
             (variants[k].sector_angle == variants[ref].sector_angle &&
              variants[k].initial_steps > variants[ref].initial_steps)))
          ref = k;
      return ref;
    }

    /// The price of each simplification: every variant's limit against
    /// that of the most faithful variant of its element.
    void
    compare_variants(const std::vector<Variant>             &variants,
                     const std::vector<std::vector<double>> &limits,
                     const std::vector<double>              &variant_wall,
                     const std::vector<Quantity>            &quantities,
                     std::ostringstream                     &text)
    {
      text << "Variants compared (limits as above; difference against "
              "the most faithful variant of the same element: largest "
              "sector, most initial load steps):\n";
      for (unsigned int vi = 0; vi < variants.size(); ++vi)
        {
          if (limits[vi].empty())
            continue;
          const unsigned int ref = most_faithful(variants, limits, vi);
          text << "  " << std::setw(40) << std::left << variants[vi].label
               << std::right;
          for (const unsigned int q : {0u, 1u})
            {
              const double d = limits[vi][q] / limits[ref][q] - 1;
              text << "  " << quantities[q].label << " " << std::setprecision(8)
                   << limits[vi][q] << " (" << std::showpos
                   << std::setprecision(3) << 100 * d << std::noshowpos
                   << " %)";
            }
          text << "  wall " << std::setprecision(3) << variant_wall[vi]
               << " s (all levels)\n";
        }
      text << '\n';
    }

    /// The control of @p contact's mode: its name on the screen, its
    /// study.csv column and the factor from the program's unit to the
    /// user's.
    void
    control_names(const Parameters::Contact &contact,
                  std::string               &name,
                  std::string               &column,
                  std::string               &unit,
                  double                    &factor)
    {
      factor = 1;
      if (contact.mode == Parameters::ContactMode::nip_angle)
        {
          name   = "theta0";
          column = "prescribed_theta0_deg";
          unit   = "deg";
          factor = 180. / numbers::PI;
        }
      else if (contact.mode == Parameters::ContactMode::indentation)
        {
          name   = "u0";
          column = "prescribed_u0_mm";
          unit   = "mm";
        }
      else
        {
          name   = contact.load_unit.is_total_force() ? "F" : "P";
          column = "prescribed_" + contact.load_unit.column_name();
          unit   = contact.load_unit.name;
          factor = 1. / contact.load_unit.to_n_per_mm;
        }
    }

    /// The nips the study runs: those of @p chosen, or every value of
    /// Contact/Values; one unnamed nip for a pressure scene. The header
    /// columns of the nips go to @p csv_header.
    std::vector<StudiedNip>
    studied_nips(const Parameters::AllParameters &parameters,
                 const Parameters::StudyValues   &chosen,
                 std::string                     &csv_header)
    {
      const auto &contact = parameters.contact;
      if (contact.mode == Parameters::ContactMode::none)
        return {StudiedNip()};
      const std::vector<double> &values =
        chosen.values.empty() ? contact.values : chosen.values;
      std::string name, column, unit;
      double      factor = 1;
      control_names(contact, name, column, unit, factor);
      csv_header = "nip," + column + ",";
      std::vector<StudiedNip> nips;
      for (unsigned int k = 0; k < values.size(); ++k)
        {
          StudiedNip         nip;
          std::ostringstream v, number;
          v << std::setprecision(8) << values[k] * factor;
          number << std::setw(2) << std::setfill('0') << k + 1;
          nip.value     = values[k];
          nip.label     = name + " = " + v.str() + " " + unit;
          nip.directory = values.size() > 1 ? "nip-" + number.str() + "/" : "";
          nip.csv_columns = std::to_string(k + 1) + "," + v.str() + ",";
          nips.push_back(nip);
        }
      return nips;
    }
  } // namespace

  int
  run_refinement_study(const Parameters::AllParameters &parameters,
                       const MPI_Comm                   communicator,
                       const Parameters::StudyValues   &chosen)
  {
    const bool root = Utilities::MPI::this_mpi_process(communicator) == 0;
    ConditionalOStream pcout(std::cout, root);
    const bool         contact =
      parameters.contact.mode != Parameters::ContactMode::none;
    const auto &quantities = contact ? contact_quantities : pressure_quantities;
    const std::vector<Variant>    variants = make_variants(parameters);
    const std::string            &top      = parameters.output.directory;
    std::string                   nip_columns;
    const std::vector<StudiedNip> nips =
      studied_nips(parameters, chosen, nip_columns);
    if (nips.size() > 1)
      pcout << "Study: " << nips.size() << " nips (every one of "
            << (chosen.values.empty() ? "Contact/Values" : "Study/Values")
            << "), " << variants.size() << " variant(s), "
            << parameters.study.levels.size() << " level(s) each" << std::endl;

    std::vector<Run>  runs;
    const std::string failure =
      run_all(parameters, nips, variants, runs, communicator);

    // One table per nip and element; errors against the extrapolated value
    // of that sequence.
    std::ostringstream text, csv;
    write_csv_header(nip_columns, quantities, csv);
    for (unsigned int k = 0; k < nips.size(); ++k)
      {
        std::vector<std::vector<double>> limits(variants.size());
        std::vector<double>              variant_wall(variants.size(), 0.);
        for (const auto &r : runs)
          if (r.nip == k)
            variant_wall[r.variant] += r.wall;
        for (unsigned int vi = 0; vi < variants.size(); ++vi)
          limits[vi] = report_variant(
            nips[k], k, variants[vi], vi, runs, quantities, contact, text, csv);
        if (!parameters.study.sector_angles.empty() ||
            !parameters.study.initial_steps.empty())
          compare_variants(variants, limits, variant_wall, quantities, text);
      }
    if (!failure.empty())
      text << "The study stopped: " << failure << "\n";
    pcout << '\n' << text.str();
    if (root)
      {
        make_directories(top);
        write_atomically(top + "/study.csv",
                         [&](std::ostream &out) { out << csv.str(); });
        write_atomically(top + "/study.txt",
                         [&](std::ostream &out) { out << text.str(); });
      }
    if (!failure.empty())
      {
        if (root)
          std::cerr << "rollnip: error: study: " << failure << std::endl;
        return 1;
      }
    return 0;
  }
} // namespace rollnip
