#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <rollnip/app/accuracy_target.h>
#include <rollnip/app/nip_study.h>
#include <rollnip/output/atomic_file.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>

namespace rollnip
{
  namespace Parameters
  {
    namespace
    {
      /// The names users may give in Accuracy/Target quantities.
      NipQuantity::Index
      quantity_by_name(const std::string &name)
      {
        static const std::vector<std::pair<std::string, NipQuantity::Index>>
          names = {{"theta0", NipQuantity::theta0},
                   {"P", NipQuantity::load},
                   {"u0", NipQuantity::indentation},
                   {"b", NipQuantity::half_chord},
                   {"2b", NipQuantity::half_chord},
                   {"peak pressure", NipQuantity::peak_pressure},
                   {"mean pressure", NipQuantity::mean_pressure},
                   {"bond sigma_rr", NipQuantity::bond_sigma_rr},
                   {"bond sigma_rtheta", NipQuantity::bond_sigma_rtheta}};
        for (const auto &entry : names)
          if (entry.first == name)
            return entry.second;
        AssertThrow(false,
                    ExcMessage("Accuracy/Target quantities: '" + name +
                               "' is not one of theta0, P, u0, b, 2b, peak "
                               "pressure, mean pressure, bond sigma_rr, bond "
                               "sigma_rtheta"));
        return NipQuantity::load;
      }

      /// "0.1 %", "0.1%" or "1e-3" as a fraction; "" or "off" as 0.
      double
      relative_error(const std::string &text)
      {
        std::string t = Utilities::trim(text);
        if (t.empty() || t == "off")
          return 0;
        double scale = 1;
        if (t.back() == '%')
          {
            scale = 0.01;
            t     = Utilities::trim(t.substr(0, t.size() - 1));
          }
        std::size_t used  = 0;
        double      value = std::numeric_limits<double>::quiet_NaN();
        try
          {
            value = std::stod(t, &used);
          }
        catch (const std::exception &)
          {
            used = 0;
          }
        AssertThrow(used > 0 && used == t.size() && std::isfinite(value),
                    ExcMessage("Accuracy/Target: '" + text +
                               "' is not a number (give a relative error such "
                               "as 0.1 % or 1e-3, or off)"));
        value *= scale;
        AssertThrow(value > 0 && value < 0.5,
                    ExcMessage("Accuracy/Target: '" + text +
                               "' must lie between 0 and 50 %"));
        return value;
      }
    } // namespace

    void
    AccuracyTarget::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Accuracy");
      prm.declare_entry(
        "Target",
        "off",
        Patterns::Anything(),
        "The relative error a contact run must reach, e.g. '0.1 %' or "
        "'1e-3'; 'off' (default): the mesh and element of the file. With a "
        "target the program chooses the element and the mesh level, cheapest "
        "first, solves with the error estimate and refines until the "
        "estimated error of every Target quantity of every nip is within it "
        "(doc/accuracy.md)");
      prm.declare_entry(
        "Target quantities",
        "P, 2b",
        Patterns::Anything(),
        "The numbers the target applies to: theta0, P, u0, b (or 2b), peak "
        "pressure, mean pressure, bond sigma_rr, bond sigma_rtheta");
      prm.leave_subsection();
    }

    void
    AccuracyTarget::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Accuracy");
      target = relative_error(prm.get("Target"));
      quantities.clear();
      for (const auto &name :
           Utilities::split_string_list(prm.get("Target quantities")))
        {
          const auto q = quantity_by_name(Utilities::trim(name));
          if (std::find(quantities.begin(), quantities.end(), q) ==
              quantities.end())
            quantities.push_back(q);
        }
      AssertThrow(!quantities.empty(),
                  ExcMessage("Accuracy/Target quantities: name at least one "
                             "quantity"));
      prm.leave_subsection();
    }

    void
    AccuracyTarget::check(const AllParameters &p) const
    {
      if (target == 0)
        return;
      AssertThrow(p.contact.mode != ContactMode::none,
                  ExcMessage("Accuracy/Target needs a contact scene "
                             "(Contact/Mode = nip angle, load or "
                             "indentation)"));
      AssertThrow(p.mesh.source == MeshSource::builtin,
                  ExcMessage("Accuracy/Target chooses the level of the "
                             "builtin mesh: it cannot refine a gmsh mesh "
                             "(Mesh/Source)"));
      AssertThrow(p.mesh.adaptive_passes == 0,
                  ExcMessage("Accuracy/Target chooses the mesh level of the "
                             "nip-fitted mesh: set Mesh/Adaptive grading "
                             "passes = 0"));
      AssertThrow(p.study.levels.empty(),
                  ExcMessage("Accuracy/Target and a Study subsection ask for "
                             "two different runs: remove one"));
    }
  } // namespace Parameters

  namespace
  {
    /// The largest relative error of each quantity of the default scene's
    /// nips (run 30, u0 = 0.5-3 mm) at level 0 on the nip-fitted mesh,
    /// against Q2-P1 at level 3 (doc/accuracy.md, the speed-accuracy
    /// front), rounded up; in the order of NipQuantity. With u0
    /// prescribed (P, its error, from the indentation rows):
    constexpr double level0_error[2][NipQuantity::n_quantities] = {
      {6e-3, 4.5e-3, 2.5e-3, 6e-3, 5.5e-3, 1e-2, 2e-2, 5e-2}, // Q1-P0
      {6e-3, 6e-4, 5e-4, 6e-3, 5e-3, 7e-3, 2e-2, 3e-2}};      // Q2-P1
    /// ... with P prescribed, where u0 is the number found (the load
    /// rows: Q1-P0 2.5e-3, Q2-P1 2.8e-4 in u0).
    constexpr double level0_error_load[2][NipQuantity::n_quantities] = {
      {6e-3, 4.5e-3, 2.5e-3, 7.5e-3, 5.5e-3, 1e-2, 2e-2, 5e-2}, // Q1-P0
      {6e-3, 6e-4, 3e-4, 6e-3, 5e-3, 7e-3, 2e-2, 3e-2}};        // Q2-P1
    /// ... and with theta0 prescribed, where P and u0 follow the contact
    /// edge (theta0 itself is given).
    constexpr double level0_error_nip_angle[2][NipQuantity::n_quantities] = {
      {1e-6, 2e-2, 1.2e-2, 2e-3, 1.5e-2, 2.2e-2, 2e-2, 2e-2},    // Q1-P0
      {1e-6, 1.4e-2, 9e-3, 6e-4, 6e-3, 1.5e-2, 1.2e-2, 1.2e-2}}; // Q2-P1

    /// The largest relative error of each quantity of the default scene's
    /// nips with Q2-P1 on the halved coarse mesh at its level 1 (the
    /// file's level-0 mesh with 10 nip cells instead of 6), against the
    /// same reference, rounded up, per control mode: u0, P and theta0
    /// prescribed. Measured: P 3.7e-5 (indentation), u0 2.3e-5 (load),
    /// P 8.6e-3 (nip angle); b 2.8e-3, 2.8e-3, 8.4e-4; peak pressure
    /// 1.6e-3, 1.6e-3, 4.5e-3; bond shear 5.1e-3, 5.1e-3, 5.0e-3.
    constexpr double halved_level1_error[3][NipQuantity::n_quantities] = {
      {3e-3, 5e-5, 3e-5, 3e-3, 2e-3, 3.5e-3, 1e-2, 1e-2}, // indentation
      {3e-3, 5e-5, 3e-5, 3e-3, 2e-3, 3.5e-3, 1e-2, 1e-2}, // load
      {1e-6, 9e-3, 5e-3, 1e-3, 5e-3, 1e-2, 1e-2, 1e-2}};  // nip angle

    /// With theta0 prescribed, the largest estimated relative error of
    /// each quantity of the default scene's nips (theta0 = 4, 8, 12 deg)
    /// extrapolated at order 1 from levels 2 and 1, its estimate from
    /// level 0 (extrapolate_first_order()), rounded up; it falls at the
    /// element's extrapolated_order() per level. Q2-P1 with
    /// q2_edge_refinements (the edge's first-order error gone,
    /// doc/accuracy.md, "Refinement at the contact edge"). Measured for P:
    /// Q1-P0 1.5e-3, 2.8e-4, 1.1e-4, 3.7e-5 at levels 2 to 5; Q2-P1
    /// 6.2e-5 at level 2.
    constexpr double extrapolated_level2_error[2][NipQuantity::n_quantities] = {
      {1e-6, 1.5e-3, 1.3e-3, 5.5e-4, 1.6e-3, 1e-3, 2.3e-3, 1e-3}, // Q1-P0
      {1e-6, 7e-5, 2e-5, 1e-5, 6e-4, 6e-5, 2.5e-4, 6e-4}};        // Q2-P1
    /// ... and of Q2-P1 on the halved coarse mesh, with the same edge
    /// refinements. Measured for P: 2.9e-4 at level 2, 3.9e-5 at level 3.
    constexpr double
      halved_extrapolated_level2_error[NipQuantity::n_quantities] =
        {1e-6, 3e-4, 3e-4, 1.5e-5, 9e-4, 3e-4, 3e-4, 5.5e-3};

    /// The edge refinements of the Q2-P1 candidates that use them: the
    /// extrapolated ones (theta0 prescribed; with 3 to 6 the extrapolated
    /// P is the same to 3e-6 of itself; without, the edge's first-order
    /// error term shows at 12 deg, where the extrapolated P of levels 0 to
    /// 2 was 5e-4 off) and the edge-refined ones under load and
    /// indentation control (b 20 times closer at level 0; with 4 its
    /// error keeps one sign over the default scene's nips, where with 5
    /// or 6 the opposite term under a small nip shows; doc/accuracy.md,
    /// "Refinement at the contact edge").
    constexpr unsigned int q2_edge_refinements = 4;

    /// With P or u0 prescribed, the largest relative error or estimate of
    /// each quantity of the default scene's nips (u0 = 0.5-3 mm) with
    /// Q2-P1 and q2_edge_refinements at level 0 on the file's mesh,
    /// against the references of doc/accuracy.md ("Refinement at the
    /// contact edge"), rounded up; per control mode: u0 and P prescribed.
    /// Measured: b 2.7e-4 and 3.7e-4 (against 6.3e-3 without edge
    /// refinements), theta0 2.8e-4 and 3.7e-4, P 2.6e-4 (estimate 2.7e-4)
    /// under indentation, u0 1.8e-4 (estimate 1.9e-4) under load. With
    /// theta0 prescribed their estimate is not reliable at a small nip:
    /// not candidates there.
    constexpr double edge_refined_level0_error[2][NipQuantity::n_quantities] = {
      {3e-4, 3e-4, 2e-4, 3e-4, 5e-3, 5.5e-4, 2e-3, 3.5e-3}, // indentation
      {4e-4, 3e-4, 2e-4, 4e-4, 5e-3, 4e-4, 2e-3, 3.5e-3}};  // load

    /// DoFs the edge refinements add to Q2-P1 at any level of the
    /// default scene (86 per halving).
    constexpr double q2_edge_refinement_dofs = 344;

    /// DoFs of the default scene's roll at level 0 per element, and of
    /// Q2-P1 on its halved coarse mesh (4 x 11 cells).
    constexpr double level0_dofs[2]     = {486, 1690};
    constexpr double halved_level0_dofs = 546;

    /// The cost of the error estimate's companion per DoF of its mesh,
    /// relative to the run's own cost per DoF: it starts from the run's
    /// answer and needs fewer iterations (measured on the default scene's
    /// four nips, one thread: 0.57 to 0.73).
    constexpr double companion_cost_per_dof = 0.7;

    /// A target is taken as predicted to be met below this fraction of
    /// it: the model is calibrated on one scene, and its level-0 errors
    /// are already the largest over that scene's nips, rounded up. A
    /// candidate that misses costs a quarter of the next level's, so the
    /// margin is not made wider than that.
    constexpr double prediction_margin = 0.8;

    /// Newton's tolerances of a target run, as fractions of the target
    /// (when looser than Nonlinear solver's): the residual, the last
    /// update and the volume constraint. Newton converges quadratically,
    /// so each stops at most one iteration short of the file's tolerance;
    /// on the default scene at 0.1 % this moves P by at most 6e-8
    /// relative (doc/accuracy.md, "An accuracy target").
    constexpr double newton_residual_of_target   = 1e-2;
    constexpr double newton_increment_of_target  = 1e-1;
    constexpr double newton_constraint_of_target = 1e-3;

    /// The control tolerance of a target run, as a fraction of the target
    /// (when that is looser than Contact/Control tolerance).
    constexpr double control_fraction_of_target = 0.01;

    unsigned int
    element_index(const Parameters::Element e)
    {
      return e == Parameters::Element::q1_p0 ? 0 : 1;
    }

    std::string
    element_name(const Parameters::Element e)
    {
      return e == Parameters::Element::q1_p0 ? "Q1-P0" : "Q2-P1";
    }

    /// "Q2-P1 at mesh level 1 of the halved coarse mesh", and the like.
    std::string
    candidate_name(const AccuracyCandidate &c)
    {
      return element_name(c.element) + " at mesh level " +
             std::to_string(c.level) +
             (c.halved_mesh ? " of the halved coarse mesh" : "") +
             (c.edge_refinements
                ? " with " + std::to_string(c.edge_refinements) +
                    " edge refinements"
                : "") +
             (c.extrapolated ? " extrapolated at order 1 from levels " +
                                 std::to_string(c.level - 2) + " to " +
                                 std::to_string(c.level)
                             : "");
    }

    /// The larger of @p worst and the relative estimate @p e; inf if @p e
    /// is not finite: a nip without an estimate never meets a target.
    double
    larger_estimate(const double worst, const double e)
    {
      return std::isfinite(e) ? std::max(worst, e)
                              : std::numeric_limits<double>::infinity();
    }

    /// The largest estimated relative error of @p q over @p rows; inf if
    /// a nip has none.
    double
    largest_estimate(const std::vector<NipRow> &rows,
                     const NipQuantity::Index   q)
    {
      double worst = 0;
      for (const auto &row : rows)
        worst =
          larger_estimate(worst, row.error.relative(q, nip_numbers(row)[q]));
      return worst;
    }

    /// One candidate's run: what it was and what it reached.
    struct Attempt
    {
      AccuracyCandidate       candidate;
      int                     code    = 0;
      double                  seconds = 0;
      unsigned int            n_nips  = 0;
      types::global_dof_index n_dofs  = 0;
      std::vector<double>     estimate; ///< per target quantity
      bool                    met = false;
      /// An extrapolated candidate's numbers, per nip.
      std::vector<ExtrapolatedNumbers> extrapolated;
    };

    /// The largest estimated relative error of @p q over the extrapolated
    /// @p nips; inf if one is not finite.
    double
    largest_estimate(const std::vector<ExtrapolatedNumbers> &nips,
                     const NipQuantity::Index                q)
    {
      double worst = 0;
      for (const auto &x : nips)
        worst = larger_estimate(worst, x.error[q] / std::abs(x.value[q]));
      return worst;
    }

    /// Solves the sweep of @p p at its level and at the two below, nip
    /// by nip, each level from the one below (CoarserLevels), all without
    /// the error estimate's companion, and extrapolates each nip's numbers
    /// at order 1 into @p a. The output directory holds the finest
    /// level's files, extrapolation/level-K the nip characteristic of
    /// level K. Returns the exit code.
    int
    solve_extrapolated(Parameters::AllParameters p,
                       Attempt                  &a,
                       std::vector<NipRow>      &rows,
                       MPI_Comm                  communicator)
    {
      p.accuracy.error_estimate = false;
      const unsigned int level  = p.mesh.global_refinements;
      CoarserLevels      below;
      for (const unsigned int k : {level - 2, level - 1})
        {
          below.levels.push_back(k);
          below.directories.push_back(
            p.output.directory + "/extrapolation/level-" + std::to_string(k));
        }
      const int code =
        run_nip_study(p, communicator, &rows, nullptr, true, &below);
      if (Utilities::MPI::this_mpi_process(communicator) == 0)
        for (unsigned int i = 0; i < below.levels.size(); ++i)
          if (!below.rows[i].empty())
            std::cout << "Mesh level " << below.levels[i] << " ("
                      << below.rows[i].front().n_dofs
                      << " DoFs): " << below.rows[i].size() << " nip(s) in "
                      << std::fixed << std::setprecision(2) << below.seconds[i]
                      << " s, each from "
                      << (i == 0 ? std::string("the nip before")
                                 : "the same nip at level " +
                                     std::to_string(below.levels[i - 1]))
                      << ", nip characteristic in " << below.directories[i]
                      << std::defaultfloat << std::endl;
      if (code)
        return code;
      AssertThrow(below.rows[0].size() == rows.size() &&
                    below.rows[1].size() == rows.size(),
                  ExcMessage("Accuracy/Target: the three mesh levels solved "
                             "different numbers of nips"));
      for (unsigned int i = 0; i < rows.size(); ++i)
        a.extrapolated.push_back(
          extrapolate_first_order(nip_numbers(rows[i]),
                                  nip_numbers(below.rows[1][i]),
                                  nip_numbers(below.rows[0][i]),
                                  p.discretization.element));
      return 0;
    }

    /// Solves the sweep of @p parameters with @p candidate's element and
    /// level and the error estimate on.
    Attempt
    attempt(const Parameters::AllParameters  &parameters,
            const Parameters::AccuracyTarget &target,
            const AccuracyCandidate          &candidate,
            MPI_Comm                          communicator)
    {
      Parameters::AllParameters p = parameters;
      p.discretization.element    = candidate.element;
      p.mesh.global_refinements   = candidate.level;
      if (candidate.halved_mesh)
        halve_coarse_mesh(p.mesh);
      if (p.nip_fitted_mesh())
        p.mesh.edge_refinements = candidate.edge_refinements;
      p.accuracy.error_estimate = true;
      // P or u0 met to a hundredth of the target, not to a millionth:
      // the last control iteration moves no number by more than that,
      // and the contact iteration works to a tenth of it.
      p.contact.control_tolerance =
        std::max(p.contact.control_tolerance,
                 control_fraction_of_target * target.target);
      // Newton likewise: its last iteration would move no number by more
      // than a ten-thousandth of the target (in the companion too).
      auto &newton = p.nonlinear_solver;
      newton.residual_tolerance =
        std::max(newton.residual_tolerance,
                 newton_residual_of_target * target.target);
      newton.increment_tolerance =
        std::max(newton.increment_tolerance,
                 newton_increment_of_target * target.target);
      newton.constraint_tolerance =
        std::max(newton.constraint_tolerance,
                 newton_constraint_of_target * target.target);
      Attempt             a;
      std::vector<NipRow> rows;
      a.candidate = candidate;
      Timer timer;
      a.code    = candidate.extrapolated
                    ? solve_extrapolated(p, a, rows, communicator)
                    : run_nip_study(p, communicator, &rows);
      a.seconds = timer.wall_time();
      a.n_nips  = rows.size();
      a.n_dofs  = rows.empty() ? 0 : rows.front().n_dofs;
      a.met     = a.code == 0 && !rows.empty();
      for (const auto q : target.quantities)
        {
          // A stopped run has no estimate (nor extrapolated numbers).
          a.estimate.push_back(
            a.code != 0              ? std::numeric_limits<double>::quiet_NaN()
            : candidate.extrapolated ? largest_estimate(a.extrapolated, q)
                                     : largest_estimate(rows, q));
          a.met = a.met && a.estimate.back() <= target.target;
        }
      return a;
    }

    /// The next candidate: the cheapest untried one, dearer than the
    /// last, whose predicted errors (scaled by @p calibration per
    /// quantity) are all within the margin of the target; if none is
    /// predicted to meet it, the one predicted to come closest; -1 when
    /// none is left.
    int
    next_candidate(const std::vector<AccuracyCandidate> &candidates,
                   const std::vector<bool>              &tried,
                   const double                          last_cost,
                   const Parameters::AllParameters      &parameters,
                   const Parameters::AccuracyTarget     &target,
                   const std::vector<double>            &calibration)
    {
      int    closest = -1;
      double best    = std::numeric_limits<double>::infinity();
      for (unsigned int c = 0; c < candidates.size(); ++c)
        {
          if (tried[c] || candidates[c].cost <= last_cost)
            continue;
          // Without the nip-fitted mesh an edge-refined run would be the
          // plain one again.
          if (candidates[c].edge_refinements > 0 &&
              !candidates[c].extrapolated && !parameters.nip_fitted_mesh())
            continue;
          // The largest predicted error over the target quantities, in
          // units of the target.
          double worst = 0;
          for (unsigned int k = 0; k < target.quantities.size(); ++k)
            worst = std::max(worst,
                             calibration[k] *
                               predicted_error(candidates[c],
                                               target.quantities[k],
                                               parameters.contact.mode) /
                               target.target);
          if (worst <= prediction_margin)
            return c;
          if (worst < best)
            {
              best    = worst;
              closest = c;
            }
        }
      return closest;
    }

    /// accuracy_target.csv: every candidate tried.
    void
    write_attempts(const std::vector<Attempt>       &attempts,
                   const Parameters::AccuracyTarget &target,
                   const std::string                &dir)
    {
      write_atomically(dir + "/accuracy_target.csv", [&](std::ostream &out) {
        out << "element,level,coarse_mesh,answer,dofs,nips,wall_time_s,"
               "target_relative,edge_refinements";
        for (const auto q : target.quantities)
          out << ",estimated_relative_error_" << NipQuantity::key(q);
        out << ",met\n" << std::setprecision(6);
        for (const auto &a : attempts)
          {
            out << element_name(a.candidate.element) << ',' << a.candidate.level
                << ',' << (a.candidate.halved_mesh ? "halved" : "file") << ','
                << (a.candidate.extrapolated ? "extrapolated" : "solved") << ','
                << a.n_dofs << ',' << a.n_nips << ',' << a.seconds << ','
                << target.target << ',' << a.candidate.edge_refinements;
            for (const double e : a.estimate)
              out << ',' << e;
            out << ',' << (a.met ? "yes" : "no") << '\n';
          }
      });
    }

    /// "N_per_mm" as "N/mm".
    std::string
    screen_unit(const NipQuantity::Index q)
    {
      std::string u = NipQuantity::unit(q);
      if (const auto i = u.find("_per_"); i != std::string::npos)
        u.replace(i, 5, "/");
      return u;
    }

    /// accuracy_target_values.csv: each nip's numbers extrapolated by
    /// attempt @p a and their estimated errors; the target quantities on
    /// the screen (@p out).
    void
    write_extrapolated(const Attempt                    &a,
                       const Parameters::AccuracyTarget &target,
                       const std::string                &dir,
                       std::ostream                     &out)
    {
      write_atomically(
        dir + "/accuracy_target_values.csv", [&](std::ostream &csv) {
          csv << "nip";
          for (unsigned int q = 0; q < NipQuantity::n_quantities; ++q)
            {
              const auto i = NipQuantity::Index(q);
              csv << ',' << NipQuantity::key(i) << '_' << NipQuantity::unit(i)
                  << ',' << NipQuantity::key(i) << "_err_"
                  << NipQuantity::unit(i);
            }
          csv << '\n' << std::setprecision(10);
          for (unsigned int n = 0; n < a.extrapolated.size(); ++n)
            {
              csv << n + 1;
              for (unsigned int q = 0; q < NipQuantity::n_quantities; ++q)
                csv << ',' << a.extrapolated[n].value[q] << ','
                    << a.extrapolated[n].error[q];
              csv << '\n';
            }
        });
      out << "Extrapolated at order 1 from mesh levels "
          << a.candidate.level - 2 << " to " << a.candidate.level
          << " (accuracy_target_values.csv; the other files are level "
          << a.candidate.level << "'s):\n";
      for (unsigned int n = 0; n < a.extrapolated.size(); ++n)
        {
          const auto        &x = a.extrapolated[n];
          std::ostringstream line;
          line << "  nip " << n + 1
               << ", theta0 = " << x.value[NipQuantity::theta0] << " deg:";
          for (unsigned int k = 0; k < target.quantities.size(); ++k)
            {
              const auto q = target.quantities[k];
              line << (k ? ", " : " ") << NipQuantity::label(q) << " = "
                   << std::setprecision(7) << x.value[q] << ' '
                   << screen_unit(q) << " (estimated error "
                   << std::setprecision(2)
                   << 100 * x.error[q] / std::abs(x.value[q]) << " %)"
                   << std::setprecision(6);
            }
          out << line.str() << '\n';
        }
      out << std::flush;
    }

    /// The screen line of attempt @p a.
    std::string
    describe(const Attempt &a, const Parameters::AccuracyTarget &target)
    {
      std::ostringstream out;
      out << candidate_name(a.candidate) << " (" << a.n_dofs << " DoFs, "
          << std::fixed << std::setprecision(2) << a.seconds << " s for "
          << a.n_nips << " nip(s)): ";
      // A stopped run's own line says why.
      if (a.code != 0)
        return out.str() + "stopped";
      out << "largest estimated";
      for (unsigned int k = 0; k < target.quantities.size(); ++k)
        out << (k ? ", " : " ") << NipQuantity::label(target.quantities[k])
            << ' ' << std::setprecision(3) << 100 * a.estimate[k] << " %";
      return out.str();
    }
  } // namespace

  void
  halve_coarse_mesh(Parameters::Mesh &mesh)
  {
    const unsigned int beyond = mesh.circumferential_cells > mesh.nip_cells
                                  ? mesh.circumferential_cells - mesh.nip_cells
                                  : 2;
    mesh.radial_cells         = std::max(1u, (mesh.radial_cells + 1) / 2);
    mesh.nip_cells            = std::max(2u, (5 * mesh.nip_cells + 3) / 6);
    mesh.circumferential_cells =
      mesh.nip_cells + std::max(2u, (beyond + 1) / 2);
  }

  std::vector<AccuracyCandidate>
  accuracy_candidates()
  {
    // The run's DoFs and its companion's, one level finer at level 0 and
    // one coarser above.
    auto cost = [](const unsigned int e, const unsigned int level) {
      const double dofs = level0_dofs[e] * std::pow(4., level);
      return dofs * (1 + companion_cost_per_dof * (level == 0 ? 4. : 0.25));
    };
    std::vector<AccuracyCandidate> c;
    for (unsigned int level = 0; level <= 4; ++level)
      c.push_back({Parameters::Element::q1_p0, level, cost(0, level)});
    for (unsigned int level = 0; level <= 3; ++level)
      c.push_back({Parameters::Element::q2_p1, level, cost(1, level)});
    // With the edge refinements (P or u0 prescribed): their DoFs at the
    // run's level and at its companion's.
    for (unsigned int level = 0; level <= 3; ++level)
      c.push_back({Parameters::Element::q2_p1,
                   level,
                   cost(1, level) +
                     q2_edge_refinement_dofs * (1 + companion_cost_per_dof),
                   false,
                   false,
                   q2_edge_refinements});
    // Extrapolated (theta0 prescribed): the three levels, no companion
    // (the edge refinements add under 400 DoFs to each level).
    for (unsigned int e = 0; e < 2; ++e)
      for (unsigned int level = 2; level <= (e == 0 ? 5u : 4u); ++level)
        c.push_back(
          {e == 0 ? Parameters::Element::q1_p0 : Parameters::Element::q2_p1,
           level,
           level0_dofs[e] * 21 * std::pow(4., level - 2.),
           false,
           true,
           e == 0 ? 0u : q2_edge_refinements});
    for (unsigned int level = 2; level <= 3; ++level)
      c.push_back({Parameters::Element::q2_p1,
                   level,
                   halved_level0_dofs * 21 * std::pow(4., level - 2.),
                   true,
                   true,
                   q2_edge_refinements});
    // Its level 0 would need the finer companion and gain nothing.
    for (unsigned int level = 1; level <= 3; ++level)
      c.push_back({Parameters::Element::q2_p1,
                   level,
                   halved_level0_dofs * std::pow(4., level) *
                     (1 + companion_cost_per_dof * 0.25),
                   true});
    std::sort(c.begin(), c.end(), [](const auto &a, const auto &b) {
      return a.cost < b.cost;
    });
    return c;
  }

  double
  predicted_error(const AccuracyCandidate      &candidate,
                  const NipQuantity::Index      q,
                  const Parameters::ContactMode mode)
  {
    if (candidate.extrapolated)
      return mode == Parameters::ContactMode::nip_angle
               ? (candidate.halved_mesh
                    ? halved_extrapolated_level2_error[q]
                    : extrapolated_level2_error[element_index(
                        candidate.element)][q]) *
                   std::pow(2.,
                            extrapolated_order(candidate.element) *
                              (2. - candidate.level))
               : std::numeric_limits<double>::infinity();
    const double p = error_order(candidate.element, q, mode);
    if (candidate.edge_refinements > 0)
      return mode == Parameters::ContactMode::nip_angle
               ? std::numeric_limits<double>::infinity()
               : edge_refined_level0_error
                     [mode == Parameters::ContactMode::indentation ? 0 : 1][q] *
                   std::pow(2., -p * candidate.level);
    if (candidate.halved_mesh)
      {
        const unsigned int m = mode == Parameters::ContactMode::indentation ? 0
                               : mode == Parameters::ContactMode::load      ? 1
                                                                            : 2;
        return halved_level1_error[m][q] *
               std::pow(2., -p * (double(candidate.level) - 1));
      }
    const auto &table =
      mode == Parameters::ContactMode::nip_angle ? level0_error_nip_angle
      : mode == Parameters::ContactMode::load    ? level0_error_load
                                                 : level0_error;
    return table[element_index(candidate.element)][q] *
           std::pow(2., -p * candidate.level);
  }

  namespace
  {
    /// @p requested with the quantity the contact mode prescribes (P under
    /// load control, u0 under indentation, theta0 at a given nip angle;
    /// its "error" is the control tolerance) replaced by the one the mode
    /// answers in its place (u0, P, P), said on @p out.
    Parameters::AccuracyTarget
    answered_quantities(const Parameters::AccuracyTarget &requested,
                        const Parameters::ContactMode     mode,
                        ConditionalOStream               &out)
    {
      using Mode = Parameters::ContactMode;
      const auto [given, found] =
        mode == Mode::load
          ? std::make_pair(NipQuantity::load, NipQuantity::indentation)
        : mode == Mode::indentation
          ? std::make_pair(NipQuantity::indentation, NipQuantity::load)
          : std::make_pair(NipQuantity::theta0, NipQuantity::load);
      Parameters::AccuracyTarget target = requested;
      target.quantities.clear();
      for (auto q : requested.quantities)
        {
          if (q == given)
            {
              out << "Accuracy target: " << NipQuantity::label(given)
                  << " is prescribed in this contact mode; the target "
                     "applies to "
                  << NipQuantity::label(found) << " in its place" << std::endl;
              q = found;
            }
          if (std::find(target.quantities.begin(),
                        target.quantities.end(),
                        q) == target.quantities.end())
            target.quantities.push_back(q);
        }
      return target;
    }
  } // namespace

  int
  run_to_accuracy_target(const Parameters::AllParameters  &parameters,
                         const Parameters::AccuracyTarget &requested,
                         MPI_Comm                          communicator)
  {
    const bool root = Utilities::MPI::this_mpi_process(communicator) == 0;
    ConditionalOStream               pcout(std::cout, root);
    const Parameters::AccuracyTarget target =
      answered_quantities(requested, parameters.contact.mode, pcout);
    const auto           candidates = accuracy_candidates();
    std::vector<bool>    tried(candidates.size(), false);
    std::vector<double>  calibration(target.quantities.size(), 1.);
    std::vector<Attempt> attempts;
    Timer                timer;
    int                  c =
      next_candidate(candidates, tried, -1, parameters, target, calibration);
    while (c >= 0)
      {
        tried[c] = true;
        pcout << "Accuracy target " << 100 * target.target << " %: trying "
              << candidate_name(candidates[c]) << std::endl;
        attempts.push_back(
          attempt(parameters, target, candidates[c], communicator));
        const Attempt &a = attempts.back();
        write_attempts(attempts, target, parameters.output.directory);
        pcout << "Accuracy target: " << describe(a, target)
              << (a.code != 0 ? ""
                  : a.met     ? " -> met"
                              : " -> not met")
              << std::endl;
        if (a.met || a.code != 0)
          break;
        // The scene's own error level against the default scene's.
        for (unsigned int k = 0; k < target.quantities.size(); ++k)
          calibration[k] =
            a.estimate[k] / predicted_error(candidates[c],
                                            target.quantities[k],
                                            parameters.contact.mode);
        c = next_candidate(candidates,
                           tried,
                           candidates[c].cost,
                           parameters,
                           target,
                           calibration);
      }
    const Attempt &last = attempts.back();
    const auto    &dir  = parameters.output.directory;
    if (root)
      {
        // Only the last attempt's files stay: an earlier extrapolated
        // candidate's coarse levels and numbers would not be this run's.
        // A failed extrapolated attempt keeps the levels it solved.
        std::error_code ignored;
        if (!last.candidate.extrapolated || last.code != 0)
          std::filesystem::remove(dir + "/accuracy_target_values.csv", ignored);
        if (!last.candidate.extrapolated)
          std::filesystem::remove_all(dir + "/extrapolation", ignored);
        else if (last.code == 0)
          write_extrapolated(last, target, dir, std::cout);
      }
    if (last.code != 0)
      return last.code; // the sweep said why
    if (root)
      {
        if (last.met)
          std::cout << "Accuracy target " << 100 * target.target
                    << " % met with " << candidate_name(last.candidate)
                    << " after " << attempts.size() << " run(s), " << std::fixed
                    << std::setprecision(2) << timer.wall_time()
                    << " s in all; the results files are "
                    << (last.candidate.extrapolated
                          ? "those of level " +
                              std::to_string(last.candidate.level) +
                              ", the extrapolated numbers in "
                              "accuracy_target_values.csv"
                          : std::string("that run's"))
                    << std::defaultfloat << std::endl;
        else
          std::cerr << "rollnip: error: Accuracy/Target " << 100 * target.target
                    << " % is not met by any element and level up to "
                    << candidate_name(last.candidate) << " ("
                    << describe(last, target) << "); the files in '"
                    << parameters.output.directory << "' hold that run"
                    << std::endl;
      }
    return last.met ? 0 : 1;
  }
} // namespace rollnip
