#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <rollnip/app/nip_report.h>
#include <rollnip/app/nip_study.h>
#include <rollnip/boundary_ids.h>
#include <rollnip/contact/counter_surface.h>
#include <rollnip/contact/inverse_contact.h>
#include <rollnip/contact/nip_control.h>
#include <rollnip/contact/nip_estimates.h>
#include <rollnip/contact/two_roll_contact.h>
#include <rollnip/geometry/angles.h>
#include <rollnip/interrupt.h>
#include <rollnip/material/hardness.h>
#include <rollnip/material/material_table.h>
#include <rollnip/output/atomic_file.h>
#include <rollnip/output/polyline_vtp.h>
#include <rollnip/output/silence_cerr.h>
#include <rollnip/output/stale_nip_directories.h>
#include <rollnip/output/sweep_pvd.h>
#include <rollnip/output/units.h>
#include <rollnip/rolling/mate_rolling.h>
#include <rollnip/rolling/rolling_evaluation.h>
#include <rollnip/rolling/rolling_parameters.h>
#include <rollnip/rolling/steady_rolling_report.h>
#include <rollnip/rolling/steady_rolling_sweep.h>
#include <rollnip/rolling/thermal_fixed_point.h>
#include <rollnip/run_errors.h>
#include <rollnip/scene/scene_builder.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

namespace rollnip
{
  namespace
  {
    constexpr double deg = 180. / numbers::PI;

    /// Points of the rigid indenter's outline near the nip (deformed
    /// configuration), out to three half-chords.
    std::vector<Point<dim>>
    indenter_outline(const Scene &scene, const ContactResult &r)
    {
      const double R0 = scene.description.roll.outer_radius();
      return scene.rigid_counter_surface()->outline(
        r.indentation, std::min(3 * std::max(r.half_chord, 1e-3), R0), 200);
    }

    /// The nip's pieces that are not cells of the mesh (collective, rank 0
    /// writes): the rigid indenter's outline near the nip as indenter.csv
    /// (for the plot of the deformed surface) and indenter.vtp, and the
    /// contact pressure along the deformed surface as contact_pressure.vtp.
    void
    write_nip_pieces(const Scene         &scene,
                     const ContactResult &r,
                     const std::string   &dir)
    {
      const SurfaceData data = scene.roll().surface_data(1.);
      if (Utilities::MPI::this_mpi_process(scene.roll().communicator()) != 0)
        return;
      if (scene.rigid_counter_surface())
        {
          const auto outline = indenter_outline(scene, r);
          write_atomically(dir + "/indenter.csv", [&](std::ostream &out) {
            out << "x_mm,y_mm\n" << std::setprecision(10);
            for (const auto &x : outline)
              out << x[0] << ',' << x[1] << '\n';
          });
          write_polyline_vtp(dir + "/indenter.vtp", outline, {});
        }
      std::vector<Point<dim>> points;
      std::vector<double>     pressure;
      for (const auto &s : data.outer)
        if (s.theta <= r.theta0 * (1 + 1e-12))
          {
            points.emplace_back(s.x, s.y);
            pressure.push_back(s.applied_pressure);
          }
      write_polyline_vtp(dir + "/contact_pressure.vtp",
                         points,
                         {{"contact_pressure_MPa", pressure}});
    }
  } // namespace

  namespace
  {
    /// Relative difference between P from the surface traction and the
    /// applied P above which a nip is flagged (0.2 % on the default mesh).
    constexpr double traction_mismatch_warning = 0.05;

    /// Fills the postprocessed columns of @p row from the converged nip
    /// of @p scene.
    void
    fill_nip_values(const Scene &scene, NipRow &row)
    {
      const RollProblem      &problem     = scene.roll();
      const SceneDescription &description = scene.description;
      const SurfaceData       data        = problem.surface_data(1.);
      row.max_principal_strain  = data.extremes.max_principal_stretch - 1;
      const BondExtremes bond   = bond_extremes(data.bond);
      row.bond_sigma_rr_min     = bond.sigma_rr_min;
      row.bond_sigma_rtheta_max = bond.sigma_rtheta_max_abs;
      row.load_from_traction    = load_from_traction(data.outer);
      const double b            = row.nonlinear.half_chord;
      row.hertz_load            = NipEstimates::hertz_load(description, b);
      row.thin_layer_load       = NipEstimates::thin_layer_load(description, b);
      const double P            = row.nonlinear.nip_load;
      row.hertz_half_chord = NipEstimates::hertz_half_width(description, P);
      row.thin_layer_half_chord =
        NipEstimates::thin_layer_half_width(description, P);
      row.n_dofs  = problem.n_dofs();
      row.n_cells = problem.n_cells();
    }

    /// fill_nip_values() for nip number @p n of @p nonlinear; prints the
    /// load check, and flags a nip whose check is off (the mesh does not
    /// resolve it).
    void
    evaluate_nip(const Scene &nonlinear, const unsigned int n, NipRow &row)
    {
      const bool root =
        Utilities::MPI::this_mpi_process(nonlinear.roll().communicator()) == 0;
      ConditionalOStream pcout(std::cout, root);
      fill_nip_values(nonlinear, row);
      const double difference =
        row.load_from_traction / row.nonlinear.nip_load - 1;
      // Formatted apart: std::cout's precision stays as it was.
      std::ostringstream line;
      line << "Nip " << n << ": P from the applied pressure " << std::fixed
           << std::setprecision(6) << row.nonlinear.nip_load
           << " N/mm, from the surface stress " << row.load_from_traction
           << " N/mm (difference " << std::setprecision(3) << 100 * difference
           << " %)";
      pcout << line.str() << std::endl;
      // The two agree to a fraction of a per cent on a mesh that resolves
      // the nip; far apart, the numbers above are not to be trusted.
      if (root && !(std::abs(difference) < traction_mismatch_warning))
        std::cerr << "rollnip: warning: nip " << n
                  << ": P from the surface stress differs from the applied P "
                     "by "
                  << std::setprecision(3) << 100 * std::abs(difference)
                  << " %: the mesh does not resolve this nip (refine it, or "
                     "check Geometry and Contact/Values)"
                  << std::endl;
    }

    /// Starts @p to from the converged nip of @p from, carried over to
    /// its mesh, as its last converged nip; false, and nothing done,
    /// where the meshes do not nest or the counter surface is a covered
    /// roll (then @p to starts from its own last nip, as a sweep does).
    bool
    carry_nip(Scene &from, Scene &to)
    {
      auto *mine   = dynamic_cast<InverseContact *>(&to.nip_solver());
      auto *theirs = dynamic_cast<InverseContact *>(&from.nip_solver());
      return mine && theirs && mine->start_from(*theirs);
    }

    /// The scene of @p p at mesh level @p level, solved beside the run
    /// without a word: no linear companion, no error estimate, no files,
    /// no timing table.
    Parameters::AllParameters
    silent_parameters(const Parameters::AllParameters &p,
                      const unsigned int               level)
    {
      Parameters::AllParameters c = p;
      c.mesh.global_refinements   = level;
      c.contact.compare_linear    = false;
      c.output.print_timing       = false;
      c.output.write_vtu          = false;
      c.output.write_csv          = false;
      c.accuracy.error_estimate   = false;
      return c;
    }

    /**
     * The run's contact solver as its load or indentation control sees
     * it, keeping the numbers of its last fully converged solves: from
     * the last one and the nearest other the error estimate's companion
     * takes the slope of every number along the nip curve (slopes()),
     * and so needs one solve where it would take two. Used where the companion
     * is the finer mesh (a run at level 0), which has no level-0 scene to start
     * from: the control then never needs to see through this to the
     * InverseContact.
     */
    class RecordingSolver : public NipSolver
    {
    public:
      explicit RecordingSolver(Scene &scene)
          : recorded_scene(scene)
          , solver(scene.nip_solver())
      {}

      void
      set_control_goal(const std::optional<ControlGoal> &goal) override
      {
        solver.set_control_goal(goal);
      }

      ContactResult
      solve(const double theta0) override
      {
        const ContactResult r = solver.solve(theta0);
        // A provisional solve stopped short of the curve.
        if (r.converged && !r.provisional)
          {
            NipRow row;
            row.nonlinear = r;
            fill_nip_values(recorded_scene, row);
            if (records.size() == max_records)
              records.erase(records.begin());
            records.push_back({r.theta0, nip_numbers(row)});
          }
        return r;
      }

      double
      max_nip_angle() override
      {
        return solver.max_nip_angle();
      }

      MPI_Comm
      communicator() const override
      {
        return solver.communicator();
      }

      const SceneDescription &
      scene() const override
      {
        return solver.scene();
      }

      void
      write_results(const ContactResult &result,
                    const std::string   &directory,
                    const unsigned int   step,
                    const bool           with_vtu) override
      {
        solver.write_results(result, directory, step, with_vtu);
      }

      /// d N / d log q of every number N of the last converged solve, if
      /// that was at @p theta0 (q: the controlled number, @p q_index), as
      /// the secant to the recorded solve nearest to it in log q of those
      /// at least min_step away; that step in @p step. False if none.
      bool
      slopes(const double       theta0,
             const unsigned int q_index,
             NipNumbers        &slopes,
             double            &step) const
      {
        if (records.empty() || records.back().theta0 != theta0)
          return false;
        const NipNumbers &last = records.back().numbers;
        step                   = 0;
        for (std::size_t k = 0; k + 1 < records.size(); ++k)
          {
            const double d =
              std::log(last[q_index] / records[k].numbers[q_index]);
            if (std::abs(d) >= min_step &&
                (step == 0 || std::abs(d) < std::abs(step)))
              {
                step = d;
                for (unsigned int q = 0; q < NipQuantity::n_quantities; ++q)
                  slopes[q] = (last[q] - records[k].numbers[q]) / d;
              }
          }
        return step != 0;
      }

    private:
      /// Nearer solves give a slope within the numbers' own convergence
      /// (a conformity of 1e-6 or so) of noise.
      static constexpr double      min_step    = 1e-4;
      static constexpr std::size_t max_records = 6;
      struct Record
      {
        double     theta0;
        NipNumbers numbers;
      };
      Scene              &recorded_scene;
      NipSolver          &solver;
      std::vector<Record> records;
    };

    /// The scene of the error estimate's companion solve: this one with
    /// both rolls' meshes one level coarser (one finer at level 0), no
    /// linear companion, no files.
    Parameters::AllParameters
    companion_parameters(const Parameters::AllParameters &p)
    {
      // One level coarser, or finer at level 0; the mating roll moves the
      // same way as the roll (coarser only while it has a level to drop).
      const unsigned int        level = p.mesh.global_refinements;
      const bool                finer = level == 0;
      const unsigned int        mate  = p.mating_roll.mesh.global_refinements;
      Parameters::AllParameters c = silent_parameters(p, finer ? 1 : level - 1);
      c.mating_roll.mesh.global_refinements =
        finer ? mate + 1 : (mate > 0 ? mate - 1 : 0);
      return c;
    }

    /**
     * The companion of Accuracy/Error estimate: the scene on the other
     * mesh level, which solves each nip again with the same control
     * (theta0, P or u0), without a word on the screen; the difference
     * gives every number's error (estimate_errors()). It starts from the
     * answer: its theta0, its contact pressure, its displacement carried
     * over to the other level (warm_start()) and the slope of its control
     * iteration, so that it needs a few Newton steps and two contact
     * solves (interpolate_to_target()) rather than a load ramp and a
     * search.
     */
    class ErrorCompanion
    {
    public:
      /// Builds the companion scene; one it cannot build (a mesh level
      /// that cannot hold the nip, say) leaves every nip without an
      /// estimate, and says why, instead of stopping the run.
      ErrorCompanion(const Parameters::AllParameters &p,
                     const MPI_Comm                   communicator)
          : parameters(companion_parameters(p))
          , level(p.mesh.global_refinements)
      {
        SilenceStream quiet(std::cout);
        try
          {
            scene = std::make_unique<Scene>(parameters, communicator);
            control =
              std::make_unique<NipControl>(scene->nip_solver(), parameters);
            build_pilot(communicator);
          }
        catch (const std::exception &e)
          {
            // An error of one process (memory, files) ends the run as
            // everywhere else; only what every process meets is skipped.
            if (is_local_error(e))
              {
                release();
                throw;
              }
            unavailable = "the scene at mesh level " +
                          std::to_string(parameters.mesh.global_refinements) +
                          " cannot be built (" + one_line_message(e) + ")";
            release();
          }
      }

      ~ErrorCompanion()
      {
        release();
      }

      /// Takes the run's slopes from @p run (interpolate_to_target()).
      void
      follow(const RecordingSolver &run)
      {
        path = &run;
      }

      /// Where the primary's control starts: theta0 and d log q / d log
      /// theta0 there (0: its own guess).
      struct Guess
      {
        double theta0 = 0, slope = 0;
      };

      /**
       * With the companion one level coarser, it goes first: solves the
       * nip of @p target from the pilot's nip of it one level coarser
       * again (pilot_lead()), or without a pilot from its own nip before,
       * with its own control converged in full, and hands it over to @p primary
       * as that scene's last converged nip (carry_nip()), so that the finer
       * mesh starts from the same nip, not from the one before; under load or
       * indentation control the primary's control also starts from its
       * theta0 and slope (returned). estimate() then takes these numbers.
       * At level 0 (the companion finer), or where its own solve fails, it
       * leaves nothing: the companion then follows the primary.
       */
      Guess
      lead(const double target, Scene &primary)
      {
        led = {};
        if (!control || parameters.mesh.global_refinements > level)
          return {};
        led.active = true;
        Guess guess;
        Timer timer;
        try
          {
            SilenceStream quiet(std::cout);
            // Fully converged solves only: its answer must not depend on
            // where it started (its nip before, on any number of
            // processes).
            control->allow_provisional(false);
            const Guess start = pilot_lead(target);
            NipRow      c;
            c.nonlinear = control->solve(target, start.theta0, start.slope);
            if (c.nonlinear.converged)
              {
                fill_nip_values(*scene, c);
                led.numbers = nip_numbers(c);
                carry_nip(*scene, primary);
                if (parameters.contact.mode !=
                    Parameters::ContactMode::nip_angle)
                  guess = {c.nonlinear.theta0, control->local_slope(target)};
              }
            else
              led.active = false;
          }
        catch (const std::exception &error)
          {
            if (is_local_error(error))
              throw;
            led.active = false;
          }
        // A companion that failed first follows the run instead, from the
        // run's nip (estimate()), as at level 0.
        led.seconds = timer.wall_time();
        return guess;
      }

      /// The error estimate of the converged nip @p row of @p primary,
      /// solved for @p target (a value of Contact/Values, in the program's
      /// units); @p slope is d log q / d log theta0 of the primary's
      /// control there (0: unknown).
      ErrorEstimate
      estimate(const NipRow &row,
               const double  target,
               Scene        &primary,
               const double  slope)
      {
        if (!control)
          {
            ErrorEstimate e;
            e.missing = unavailable;
            return e;
          }
        if (led.active)
          return estimate(row, led.numbers, "", led.seconds);
        Timer       timer;
        NipNumbers  numbers;
        std::string failure;
        try
          {
            SilenceStream quiet(std::cout);
            const bool    warm = warm_start(primary);
            if (!(warm && slope > 0 &&
                  interpolate_to_target(
                    target, row.nonlinear.theta0, slope, numbers)))
              failure = solve_controlled(target, row, slope, numbers);
          }
        catch (const std::exception &error)
          {
            if (is_local_error(error))
              throw;
            failure = one_line_message(error);
          }
        return estimate(row, numbers, failure, timer.wall_time());
      }

    private:
      /// The estimate of @p row from the companion's @p numbers, or why
      /// there is none (@p failure), after @p seconds of its solves.
      ErrorEstimate
      estimate(const NipRow      &row,
               const NipNumbers  &numbers,
               const std::string &failure,
               const double       seconds) const
      {
        const unsigned int other = parameters.mesh.global_refinements;
        ErrorEstimate      e;
        if (failure.empty())
          e = estimate_errors(nip_numbers(row),
                              numbers,
                              parameters.discretization.element,
                              parameters.contact.mode,
                              level,
                              other);
        else
          e.missing = "the same nip at mesh level " + std::to_string(other) +
                      " did not converge (" + failure + ")";
        e.companion_level   = other;
        e.companion_seconds = seconds;
        return e;
      }

      /// The numbers of the converged nip, solved for @p target with the
      /// control from the primary's @p row and @p slope; empty, or why it
      /// failed.
      std::string
      solve_controlled(const double  target,
                       const NipRow &row,
                       const double  slope,
                       NipNumbers   &numbers)
      {
        // A control of its own: the nips of earlier targets would give a
        // worse slope than the primary's.
        control = std::make_unique<NipControl>(scene->nip_solver(), parameters);
        // It starts from the primary's state on one process and from its
        // own last nip on several: only fully converged solves make its
        // answer independent of that.
        control->allow_provisional(false);
        NipRow c;
        c.nonlinear = control->solve(target, row.nonlinear.theta0, slope);
        if (!c.nonlinear.converged)
          return c.nonlinear.message;
        fill_nip_values(*scene, c);
        numbers = nip_numbers(c);
        return "";
      }

      /**
       * Under load or indentation control, the numbers at @p target from
       * one or two nip-angle solves instead of the control's iteration:
       * at the primary's @p theta0 (which misses the target by the
       * difference of the meshes, 1e-4 to a few 1e-3), then either every
       * number moved to the target along the primary's own slopes (where
       * the run recorded them: path) or one secant step with the
       * primary's @p slope (d log q / d log theta0) and every number
       * interpolated linearly in log q to the target. Each errs by less
       * than Contact/Control tolerance, the error the control's own last
       * solve would leave; the control's further solves, which only
       * close that gap, are saved. Returns false where the solves do not
       * get there (the control then takes over).
       */
      bool
      interpolate_to_target(const double target,
                            const double theta0,
                            const double slope,
                            NipNumbers  &numbers)
      {
        if (parameters.contact.mode == Parameters::ContactMode::nip_angle)
          return false;
        const bool by_load =
          parameters.contact.mode == Parameters::ContactMode::load;
        const double tolerance = parameters.contact.control_tolerance;
        NipRow       first, second;
        // The controlled number of a converged solve, relative to target.
        auto solve = [&](NipRow &row, const double theta) {
          row.nonlinear = scene->nip_solver().solve(theta);
          if (!row.nonlinear.converged)
            return std::numeric_limits<double>::quiet_NaN();
          fill_nip_values(*scene, row);
          return std::log(
            (by_load ? row.nonlinear.nip_load : row.nonlinear.indentation) /
            target);
        };
        const double miss_1 = solve(first, theta0);
        if (!std::isfinite(miss_1))
          return false;
        numbers = nip_numbers(first);
        if (std::abs(miss_1) < tolerance)
          return true;
        // One solve: every number moved to the target along the run's
        // nip curve. That errs by the miss times the slope's error,
        // about its secant's step plus the meshes' difference, on
        // slopes of at most about 2 in log-log.
        NipNumbers slopes;
        double     step = 0;
        if (path &&
            path->slopes(theta0,
                         by_load ? NipQuantity::load : NipQuantity::indentation,
                         slopes,
                         step) &&
            2 * std::abs(miss_1) * (std::abs(step) + slope_mesh_difference) <
              tolerance)
          {
            for (unsigned int q = 0; q < NipQuantity::n_quantities; ++q)
              numbers[q] -= slopes[q] * miss_1;
            return true;
          }
        const double miss_2 = solve(second, theta0 * std::exp(-miss_1 / slope));
        if (!std::isfinite(miss_2) ||
            !(std::abs(miss_1 * miss_2) < tolerance &&
              std::abs(miss_2) < 0.5 * std::abs(miss_1)))
          return false;
        const NipNumbers at_2 = nip_numbers(second);
        const double     w    = miss_1 / (miss_1 - miss_2);
        for (unsigned int q = 0; q < NipQuantity::n_quantities; ++q)
          numbers[q] += w * (at_2[q] - numbers[q]);
        return true;
      }

      /// The pilot one level below a coarser companion at level 1 or
      /// more, where its nip can be handed over (carry_nip(): one
      /// process, a rigid counter surface); none where it cannot be built
      /// (the companion then starts from its own nip before).
      void
      build_pilot(const MPI_Comm communicator)
      {
        const unsigned int companion_level = parameters.mesh.global_refinements;
        if (companion_level == 0 || companion_level > level ||
            Utilities::MPI::n_mpi_processes(communicator) != 1 ||
            !dynamic_cast<InverseContact *>(&scene->nip_solver()))
          return;
        pilot_parameters = std::make_unique<const Parameters::AllParameters>(
          companion_parameters(parameters));
        try
          {
            pilot = std::make_unique<Scene>(*pilot_parameters, communicator);
            pilot_control = std::make_unique<NipControl>(pilot->nip_solver(),
                                                         *pilot_parameters);
          }
        catch (const std::exception &e)
          {
            if (is_local_error(e))
              throw;
            drop_pilot();
          }
      }

      /**
       * The nip of @p target on the pilot, handed to the companion as its
       * last converged nip; under load or indentation control also its
       * theta0 and slope, where the companion's control starts. A nip
       * from the same nip one level coarser costs the companion two or
       * three solves where one from its nip before costs three to five.
       * Nothing (the companion's own start) where the pilot fails. Its
       * provisional solves are allowed: the companion's own solves,
       * converged in full, decide the answer.
       */
      Guess
      pilot_lead(const double target)
      {
        if (!pilot_control)
          return {};
        try
          {
            const ContactResult r = pilot_control->solve(target);
            if (!r.converged)
              {
                // A mesh too coarse for this nip is no quicker for the next
                // one.
                drop_pilot();
                return {};
              }
            if (!carry_nip(*pilot, *scene) ||
                parameters.contact.mode == Parameters::ContactMode::nip_angle)
              return {};
            return {r.theta0, pilot_control->local_slope(target)};
          }
        catch (const std::exception &error)
          {
            if (is_local_error(error))
              throw;
            drop_pilot();
            return {};
          }
      }

      /// Destroys the pilot's objects, its timer silenced.
      void
      drop_pilot()
      {
        pilot_control.reset();
        if (pilot)
          pilot->silence_timers();
        pilot.reset();
      }

      /// The primary's converged nip as this scene's last (carry_nip()).
      bool
      warm_start(Scene &primary)
      {
        return carry_nip(primary, *scene);
      }

      /// Destroys the companion's objects, its timer silenced (it would
      /// report on an exception in flight).
      void
      release()
      {
        drop_pilot();
        control.reset();
        if (scene)
          scene->silence_timers();
        scene.reset();
      }

      const Parameters::AllParameters parameters;
      const unsigned int              level;       ///< of the answer
      std::string                     unavailable; ///< why, if unbuilt
      /// The nip lead() solved, if it did.
      struct Led
      {
        bool       active = false;
        NipNumbers numbers{};
        double     seconds = 0; ///< wall time [s]
      } led;
      std::unique_ptr<Scene>      scene;
      std::unique_ptr<NipControl> control;
      /// One level below the companion, which lead() starts from its nip
      /// (build_pilot()); the parameters outlive the scene that keeps a
      /// reference to them.
      std::unique_ptr<const Parameters::AllParameters> pilot_parameters;
      std::unique_ptr<Scene>                           pilot;
      std::unique_ptr<NipControl>                      pilot_control;
      const RecordingSolver *path = nullptr; ///< the run's, if given
      /// How much the slopes of a number along the nip curve differ
      /// between two mesh levels, relative, at most (their discretisation
      /// error, below 1e-3 in P for Q2-P1 at level 0).
      static constexpr double slope_mesh_difference = 1e-2;
    };

    /**
     * The scenes of CoarserLevels, without a word on the screen or a
     * file of their own. A nip from the same nip one level coarser costs
     * far less than one from the last nip (a few Newton steps and two or
     * three contact iterations: the pressure and the state are there),
     * and the coarsest level is the cheapest one to take that step.
     */
    class LevelLadder
    {
    public:
      LevelLadder(const Parameters::AllParameters &p,
                  CoarserLevels                   &coarser,
                  const MPI_Comm                   communicator)
          : coarser(coarser)
      {
        coarser.rows.assign(coarser.levels.size(), {});
        coarser.seconds.assign(coarser.levels.size(), 0.);
        // Each level's directory holds its nip characteristic alone.
        if (Utilities::MPI::this_mpi_process(communicator) == 0)
          for (const auto &directory : coarser.directories)
            {
              std::error_code ignored;
              std::filesystem::remove_all(directory, ignored);
            }
        SilenceStream quiet(std::cout);
        try
          {
            build(p, communicator);
          }
        catch (...)
          {
            release();
            throw;
          }
      }

      ~LevelLadder()
      {
        release();
      }

      /// The nip of Contact/Values @p target on every level, coarsest
      /// first; empty, or why a level stopped.
      std::string
      solve(const double target);

      /// The finest level's nip as the last converged nip of @p scene.
      void
      hand_over(Scene &scene)
      {
        if (!scenes.empty())
          carry_nip(*scenes.back(), scene);
      }

      /// Each level's first @p n_nips nips, those the run has too, as its
      /// nip characteristic in its directory (collective); a nip the run
      /// did not finish is dropped from every level.
      void
      write_tables(const unsigned int n_nips, const MPI_Comm communicator);

    private:
      /// A scene and a control per level.
      void
      build(const Parameters::AllParameters &p, const MPI_Comm communicator)
      {
        for (const unsigned int level : coarser.levels)
          {
            // The scene and its control keep references to their
            // parameters: each set has its own place.
            parameters.push_back(
              std::make_unique<const Parameters::AllParameters>(
                silent_parameters(p, level)));
            scenes.push_back(
              std::make_unique<Scene>(*parameters.back(), communicator));
            controls.push_back(
              std::make_unique<NipControl>(scenes.back()->nip_solver(),
                                           *parameters.back()));
          }
      }

      /// Destroys the controls and silences the scenes' timers (they
      /// would report on an exception in flight).
      void
      release()
      {
        controls.clear();
        for (auto &s : scenes)
          s->silence_timers();
      }

      CoarserLevels                                                &coarser;
      std::vector<std::unique_ptr<const Parameters::AllParameters>> parameters;
      std::vector<std::unique_ptr<Scene>>                           scenes;
      std::vector<std::unique_ptr<NipControl>>                      controls;
    };

    std::string
    LevelLadder::solve(const double target)
    {
      SilenceStream quiet(std::cout);
      for (unsigned int i = 0; i < scenes.size(); ++i)
        {
          Timer timer;
          if (i > 0)
            carry_nip(*scenes[i - 1], *scenes[i]);
          NipRow row;
          row.nonlinear = controls[i]->solve(target);
          coarser.seconds[i] += timer.wall_time();
          if (!row.nonlinear.converged)
            return "mesh level " + std::to_string(coarser.levels[i]) + ": " +
                   row.nonlinear.message;
          fill_nip_values(*scenes[i], row);
          coarser.rows[i].push_back(row);
        }
      return "";
    }

    /// The estimate of @p row's errors as lines of contact.txt: one
    /// key = value per number, absolute, in the number's unit.
    std::string
    error_lines(const NipRow &row, const Parameters::AllParameters &p)
    {
      const ErrorEstimate &e = row.error;
      std::ostringstream   out;
      out << std::setprecision(3);
      if (!e.available)
        {
          out << "error_estimate = none ("
              << (e.missing.empty() ? "Accuracy/Error estimate = false"
                                    : e.missing)
              << ")\n";
          return out.str();
        }
      out << "# estimated errors: "
          << e.method(p.discretization.element,
                      p.contact.mode,
                      p.mesh.global_refinements)
          << '\n';
      for (unsigned int q = 0; q < NipQuantity::n_quantities; ++q)
        out << "estimated_error_" << NipQuantity::key(NipQuantity::Index(q))
            << '_' << NipQuantity::unit(NipQuantity::Index(q)) << " = "
            << e.error[q] << '\n';
      out << "error_estimate_wall_time_s = " << e.companion_seconds << '\n';
      return out.str();
    }

    /// Nip @p n's estimated errors on the screen, relative, in one line.
    void
    print_error_estimate(const NipRow      &row,
                         const unsigned int n,
                         const MPI_Comm     communicator)
    {
      if (Utilities::MPI::this_mpi_process(communicator) != 0)
        return;
      const ErrorEstimate &e = row.error;
      if (!e.available)
        {
          std::cout << "Nip " << n << ": no error estimate: " << e.missing
                    << std::endl;
          return;
        }
      const NipNumbers   v = nip_numbers(row);
      std::ostringstream line; // std::cout's format stays as it was
      line << "Nip " << n << ": estimated errors (against mesh level "
           << e.companion_level << ", " << std::fixed << std::setprecision(2)
           << e.companion_seconds << " s):";
      const char *separator = " ";
      for (unsigned int q = NipQuantity::load; q < NipQuantity::n_quantities;
           ++q)
        {
          const auto i = NipQuantity::Index(q);
          line << separator << NipQuantity::label(i) << ' '
               << std::setprecision(q >= NipQuantity::bond_sigma_rr ? 1 : 3)
               << 100 * e.relative(i, v[q]) << " %";
          separator = ", ";
        }
      std::cout << line.str() << std::endl;
    }

    /// The results files of one nip in @p dir: the problem's (status from
    /// the contact result) and the contact's, with @p error_text, the
    /// estimated errors, in contact.txt (collective).
    void
    write_nip(RollProblem         &problem,
              const ContactResult &result,
              const std::string   &dir,
              const bool           linear_companion = false,
              const std::string   &error_text       = "")
    {
      // A linear companion that failed is said once; its columns are nan.
      if (linear_companion && !result.converged &&
          Utilities::MPI::this_mpi_process(problem.communicator()) == 0)
        std::cout << "The linear companion in " << dir << " did not converge ("
                  << result.message << "); its columns are nan" << std::endl;
      RunStatus status;
      status.converged     = result.converged;
      status.load_fraction = 1.;
      status.message       = "contact: " + result.message;
      problem.write_results(status);
      write_contact_results(result, dir, error_text);
    }

    /// What the time of the sweep's PVD is: the control of the sweep.
    std::string
    sweep_time_meaning(const Parameters::AllParameters &parameters)
    {
      const auto system = parameters.output.units;
      switch (parameters.contact.mode)
        {
          case Parameters::ContactMode::load:
            return "line load P [" +
                   Units::unit(Units::Quantity::line_load, system).name + "]";
          case Parameters::ContactMode::indentation:
            return "indentation u0 [" +
                   Units::unit(Units::Quantity::length, system).name + "]";
          default:
            return "half nip angle theta0 [deg]";
        }
    }

    /// The time of nip @p r in the sweep's PVD (see sweep_time_meaning).
    double
    sweep_time(const Parameters::AllParameters &parameters,
               const ContactResult             &r)
    {
      const auto system = parameters.output.units;
      switch (parameters.contact.mode)
        {
          case Parameters::ContactMode::load:
            return Units::unit(Units::Quantity::line_load, system)(r.nip_load);
          case Parameters::ContactMode::indentation:
            return Units::unit(Units::Quantity::length, system)(r.indentation);
          default:
            return r.theta0 * degrees_per_radian;
        }
    }

    /// Where a sweep stopped: " during nip @p n of @p total; ..." with
    /// @p converged nips done.
    std::string
    where_stopped(const unsigned int n,
                  const std::size_t  total,
                  const std::size_t  converged)
    {
      return " during nip " + std::to_string(n) + " of " +
             std::to_string(total) + "; " + std::to_string(converged) +
             " converged nip(s) are in nip_characteristic.csv";
    }

    /// What the files in @p top hold after a sweep stopped.
    std::string
    files_note(const std::string &top)
    {
      return "; the files in '" + top +
             "' hold the last converged nip (contact.txt: the last "
             "iteration)";
    }

    /// Why a sweep stopped at nip @p n of @p total with @p converged
    /// nips done: the contact's @p message, or the interruption.
    std::string
    why_stopped(const std::string &message,
                const unsigned int n,
                const std::size_t  total,
                const std::size_t  converged,
                const MPI_Comm     communicator)
    {
      if (!interrupt_requested(communicator))
        return message;
      return interrupt_message() + where_stopped(n, total, converged);
    }

    /// Arms the line a signal prints at once during nip @p n (rank 0; see
    /// arm_interrupt_line()): the same line the sweep prints when it stops
    /// there.
    void
    arm_stop_line(const unsigned int n,
                  const std::size_t  total,
                  const std::size_t  converged,
                  const std::string &top,
                  const MPI_Comm     communicator)
    {
      if (Utilities::MPI::this_mpi_process(communicator) == 0)
        arm_interrupt_line("contact: ",
                           where_stopped(n, total, converged) +
                             files_note(top));
    }

    /// The nip characteristic on the screen and, whole, as
    /// @p top/nip_characteristic.csv (collective; rank 0 writes); b/h with
    /// the roll's @p cover_thickness h [mm] tells thick from thin covers.
    void
    write_nip_characteristic(const std::vector<NipRow> &rows,
                             const bool                 with_linear,
                             const double               cover_thickness,
                             const std::string         &top,
                             const MPI_Comm             communicator,
                             const bool                 print = true)
    {
      const bool root = Utilities::MPI::this_mpi_process(communicator) == 0;
      ConditionalOStream pcout(std::cout, root && print);
      // Linear theory off, or a companion that did not converge: nan.
      auto linear_value = [with_linear](const NipRow &r, const double v) {
        return with_linear && r.linear.converged
                 ? v
                 : std::numeric_limits<double>::quiet_NaN();
      };
      // The nip characteristic.
      pcout << std::endl
            << "Nip characteristic (P two-sided per unit length; b = deformed "
               "half-chord)"
            << std::endl
            << " theta0[deg]    P[N/mm]    u0[mm]   b[mm]  arc[mm]  peak f[MPa]"
               "  mean f[MPa]  max strain  P_linear  P_Hertz  P_thin"
            << std::endl;
      for (const auto &r : rows)
        pcout << std::fixed << std::setprecision(4) << std::setw(11)
              << r.nonlinear.theta0 * deg << std::setw(11)
              << r.nonlinear.nip_load << std::setw(10)
              << r.nonlinear.indentation << std::setw(8)
              << r.nonlinear.half_chord << std::setw(9) << r.nonlinear.half_arc
              << std::setw(13) << r.nonlinear.peak_pressure << std::setw(13)
              << r.nonlinear.nip_load / (2 * r.nonlinear.half_chord)
              << std::setw(12) << r.max_principal_strain << std::setw(10)
              << linear_value(r, r.linear.nip_load) << std::setw(9)
              << r.hertz_load << std::setw(8) << r.thin_layer_load << std::endl;
      if (root)
        {
          make_directories(top);
          write_atomically(
            top + "/nip_characteristic.csv", [&](std::ostream &out) {
              out << "theta0_deg,P_N_per_mm,u0_mm,half_chord_mm,half_arc_mm,"
                     "peak_pressure_MPa,mean_pressure_MPa,max_principal_strain,"
                     "bond_sigma_rr_min_MPa,bond_sigma_rtheta_max_MPa,"
                     "P_from_traction_N_per_mm,conformity,penetration,"
                     "P_linear_N_per_mm,u0_linear_mm,peak_pressure_linear_MPa,"
                     "P_hertz_N_per_mm,P_thin_layer_N_per_mm,"
                     "half_chord_over_cover_thickness,"
                     "half_chord_hertz_at_P_mm,half_chord_thin_layer_at_P_mm";
              // The estimated errors, absolute (nan: none).
              for (unsigned int q = 0; q < NipQuantity::n_quantities; ++q)
                out << ',' << NipQuantity::key(NipQuantity::Index(q)) << "_err_"
                    << NipQuantity::unit(NipQuantity::Index(q));
              out << '\n' << std::setprecision(10);
              for (const auto &r : rows)
                {
                  out << r.nonlinear.theta0 * deg << ',' << r.nonlinear.nip_load
                      << ',' << r.nonlinear.indentation << ','
                      << r.nonlinear.half_chord << ',' << r.nonlinear.half_arc
                      << ',' << r.nonlinear.peak_pressure << ','
                      << r.nonlinear.nip_load / (2 * r.nonlinear.half_chord)
                      << ',' << r.max_principal_strain << ','
                      << r.bond_sigma_rr_min << ',' << r.bond_sigma_rtheta_max
                      << ',' << r.load_from_traction << ','
                      << r.nonlinear.conformity << ','
                      << r.nonlinear.penetration << ','
                      << linear_value(r, r.linear.nip_load) << ','
                      << linear_value(r, r.linear.indentation) << ','
                      << linear_value(r, r.linear.peak_pressure) << ','
                      << r.hertz_load << ',' << r.thin_layer_load << ','
                      << r.nonlinear.half_chord / cover_thickness << ','
                      << r.hertz_half_chord << ',' << r.thin_layer_half_chord;
                  for (unsigned int q = 0; q < NipQuantity::n_quantities; ++q)
                    out << ','
                        << (r.error.available
                              ? r.error.error[q]
                              : std::numeric_limits<double>::quiet_NaN());
                  out << '\n';
                }
            });
        }
    }


    void
    LevelLadder::write_tables(const unsigned int n_nips,
                              const MPI_Comm     communicator)
    {
      for (unsigned int i = 0; i < parameters.size(); ++i)
        {
          if (coarser.rows[i].size() > n_nips)
            coarser.rows[i].resize(n_nips);
          write_nip_characteristic(
            coarser.rows[i],
            false,
            scenes[i]->description.roll.cover_thickness(),
            coarser.directories[i],
            communicator,
            false);
        }
    }

    /// Both tables of @p rows, written (not printed) at the start of a
    /// sweep and after every nip, so that a run killed later (mpirun's
    /// SIGKILL after its SIGTERM, a second signal) keeps the nips that
    /// converged.
    void
    write_tables(const std::vector<NipRow>       &rows,
                 const bool                       with_linear,
                 const Parameters::AllParameters &parameters,
                 const SceneDescription          &scene,
                 LevelLadder                     *ladder,
                 const MPI_Comm                   communicator)
    {
      const std::string &top = parameters.output.directory;
      write_nip_characteristic(rows,
                               with_linear,
                               scene.roll.cover_thickness(),
                               top,
                               communicator,
                               false);
      write_nip_report(rows, parameters, scene, top, communicator, {}, false);
      if (ladder)
        ladder->write_tables(rows.size(), communicator);
    }

    /// Removes (rank 0) and names the nip-NN directories an earlier run
    /// left in @p top beyond this run's @p n_directories.
    void
    remove_stale_nips(const std::string &top,
                      const unsigned int n_directories,
                      const MPI_Comm     communicator)
    {
      if (Utilities::MPI::this_mpi_process(communicator) != 0)
        return;
      const std::vector<std::string> removed =
        remove_stale_nip_directories(top, n_directories);
      if (!removed.empty())
        std::cout << "Output: removed " << removed.size() << " nip director"
                  << (removed.size() > 1 ? "ies" : "y")
                  << " of an earlier run from '" << top << "' ("
                  << removed.front()
                  << (removed.size() > 1 ? " .. " + removed.back() : "")
                  << "), beyond the " << n_directories << " of this run"
                  << std::endl;
    }

    /// The pieces of nip directory @p nip in the sweep's PVD, at the nip's
    /// control value: the roll (part 0), the mating roll or the rigid
    /// indenter (1), the contact pressure (2).
    void
    add_to_sweep(SweepPvd                        &pvd,
                 const Parameters::AllParameters &parameters,
                 const SceneDescription          &scene,
                 const ContactResult             &r,
                 const std::string               &nip,
                 const std::string               &vtu)
    {
      const double time = sweep_time(parameters, r);
      pvd.add(time, nip + vtu);
      pvd.add(time,
              nip +
                (scene.covered_mate() ? "/mating_roll" + vtu : "/indenter.vtp"),
              1);
      pvd.add(time, nip + "/contact_pressure.vtp", 2);
    }

    /// The nip of Contact/Values @p target of a cover that softens as it
    /// heats: the fixed point from the converged constant-modulus nip in
    /// @p row, each pass started from the last nip with @p control's
    /// slope, on a control of its own (the sweep's keeps the
    /// constant-modulus nips). Replaces row.nonlinear; the iteration's
    /// record in @p thermal, the loss factor in @p circle_factor.
    void
    soften_nip(Scene                           &scene,
               NipControl                      &control,
               const Parameters::AllParameters &parameters,
               const Parameters::Rolling       &rolling,
               const double                     target,
               NipRow                          &row,
               ThermalCoupling                 &thermal,
               CircleFactor                    &circle_factor)
    {
      Timer        clock;
      const double slope   = control.local_slope(target);
      auto         resolve = [&](const ContactResult &last) {
        NipControl pass(scene.nip_solver(), parameters);
        return pass.solve(target, last.theta0, slope);
      };
      row.nonlinear   = soften_to_fixed_point(scene.roll().body(),
                                            row.nonlinear,
                                            rolling,
                                            resolve,
                                            thermal,
                                            circle_factor);
      thermal.seconds = clock.wall_time();
    }

    /// The nip of Contact/Values @p target into row.nonlinear, the
    /// control starting from @p guess if it has one, and for a cover that
    /// softens as it heats its fixed point with the temperature
    /// (soften_nip()); returns the wall time of the first solve [s].
    double
    solve_nip(Scene                           &scene,
              NipControl                      &control,
              const Parameters::AllParameters &parameters,
              const Parameters::Rolling       *rolling,
              const double                     target,
              const ErrorCompanion::Guess     &guess,
              NipRow                          &row,
              ThermalCoupling                 &thermal,
              CircleFactor                    &circle_factor)
    {
      Timer clock;
      // A softened cover starts each nip at the constant modulus.
      const bool soften =
        rolling && rolling->enabled && rolling->softening.active();
      if (soften)
        scene.roll().body().materials().set_modulus_factor({});
      row.nonlinear        = control.solve(target, guess.theta0, guess.slope);
      const double seconds = clock.wall_time();
      if (row.nonlinear.converged && soften)
        soften_nip(scene,
                   control,
                   parameters,
                   *rolling,
                   target,
                   row,
                   thermal,
                   circle_factor);
      return seconds;
    }

    /// The first-order loss of the covered mating roll's own cover in
    /// @p row, printed on the screen.
    void
    report_mate_rolling(Scene                     &scene,
                        const Parameters::Rolling &mate,
                        NipRow                    &row)
    {
      const auto &two =
        dynamic_cast<const TwoRollContact &>(scene.nip_solver());
      row.rolling.mate     = evaluate_mate_rolling(two.mating_roll().body(),
                                               mate,
                                               row.nonlinear.half_chord);
      const MateRolling &m = row.rolling.mate;
      if (Utilities::MPI::this_mpi_process(two.communicator()) == 0)
        std::cout << std::setprecision(4)
                  << "Mating roll's cover (first order): F_r "
                  << m.rolling_resistance << " N/mm, heat " << m.power
                  << " W/m; temperature: bond " << m.bond_temperature
                  << " degC, surface " << m.surface_temperature << " degC, max "
                  << m.max_temperature << " degC" << std::endl;
    }

    /// The rolling post-process of the converged nip @p row of @p scene
    /// into @p row.rolling, its files in @p dir (collective); the loss
    /// of each circle times @p circle_factor if given, the fixed point
    /// with the temperature @p thermal.
    void
    evaluate_rolling_nip(Scene                           &scene,
                         const Parameters::AllParameters &parameters,
                         const Parameters::Rolling       &rolling,
                         const std::string               &dir,
                         const ThermalCoupling           &thermal,
                         const CircleFactor              &circle_factor,
                         NipRow                          &row)
    {
      const MPI_Comm comm = scene.roll().communicator();
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        make_directories(dir);
      MPI_Barrier(comm);
      const RollingOutput output{dir,
                                 parameters.output.write_csv,
                                 parameters.output.write_vtu};
      row.rolling         = evaluate_rolling(scene.roll().body(),
                                     row.nonlinear,
                                     rolling,
                                     parameters.contact.indenter_radius,
                                     output,
                                     circle_factor);
      row.rolling.thermal = thermal;
      if (rolling.mate && scene.description.covered_mate())
        report_mate_rolling(scene, *rolling.mate, row);
      if (rolling.full_steady && Utilities::MPI::this_mpi_process(comm) == 0)
        {
          const auto rows = steady_rolling_sweep(
            steady_rolling_scene(parameters, rolling, row.nonlinear.theta0),
            rolling,
            row.nonlinear.indentation,
            &std::cout,
            parameters.output.write_vtu ? dir : "");
          if (parameters.output.write_csv)
            write_steady_rolling(rows, dir);
          row.rolling.full = full_rolling_numbers(rows, rolling.speeds.front());
        }
    }

    /// Appends @p lines to @p dir/summary.txt (rank 0), which
    /// write_results() has just written.
    void
    append_to_summary(const std::string &dir,
                      const std::string &lines,
                      const MPI_Comm     communicator)
    {
      if (Utilities::MPI::this_mpi_process(communicator) != 0)
        return;
      const std::string  file = dir + "/summary.txt";
      std::ifstream      in(file);
      std::ostringstream content;
      content << in.rdbuf();
      in.close();
      write_atomically(file, [&](std::ostream &out) {
        out << content.str() << lines;
      });
    }

    /// The linear-theory companion of nip @p n (0-based) of a sweep, at
    /// the nonlinear nip's theta0 in @p row: solved into row.linear,
    /// written to NIP/linear (NIP the nip's directory relative to the
    /// output directory, VTU its solution file name) and added to
    /// @p linear_pvd if given.
    void
    solve_linear_companion(Scene                           &linear_scene,
                           const SceneDescription          &description,
                           const Parameters::AllParameters &parameters,
                           const unsigned int               n,
                           const std::string               &nip,
                           const std::string               &vtu,
                           SweepPvd                        *linear_pvd,
                           NipRow                          &row)
    {
      RollProblem      &linear         = linear_scene.roll();
      NipSolver        &linear_contact = linear_scene.nip_solver();
      const std::string dir =
        (nip == "." ? parameters.output.directory
                    : parameters.output.directory + "/" + nip) +
        "/linear";
      row.linear = linear_contact.solve(row.nonlinear.theta0);
      linear.set_output_directory(dir);
      write_nip(linear, row.linear, dir, true);
      linear_contact.write_results(row.linear,
                                   dir,
                                   n + 1,
                                   linear_pvd && row.linear.converged);
      if (!linear_pvd || !row.linear.converged)
        return;
      linear.write_vtu(n + 1, 1.);
      linear_pvd->add(sweep_time(parameters, row.nonlinear),
                      nip + "/linear" + vtu);
      if (description.covered_mate())
        linear_pvd->add(sweep_time(parameters, row.nonlinear),
                        nip + "/linear/mating_roll" + vtu,
                        1);
    }

    /// Writes the files of nip @p number of a sweep into @p dir: its VTU,
    /// summary (with the error estimate and the rolling numbers), contact
    /// tables and surface pieces; @p nip_seconds is its solve's wall time.
    void
    write_nip_files(Scene                           &scene,
                    const Parameters::AllParameters &parameters,
                    const NipRow                    &row,
                    const unsigned int               number,
                    const std::string               &dir,
                    const double                     nip_seconds)
    {
      RollProblem &nonlinear = scene.roll();
      NipSolver   &contact   = scene.nip_solver();
      nonlinear.set_output_directory(dir);
      if (parameters.output.write_vtu)
        nonlinear.write_vtu(number, 1.);
      // The nip's own solve time beside the post-process's, for the
      // cost of the rolling loss (benchmarks/rolling_cost.sh).
      const std::string rolling_text =
        row.rolling.available
          ? rolling_lines(row.rolling) + thermal_lines(row.rolling) +
              mate_rolling_lines(row.rolling) +
              full_rolling_lines(row.rolling) +
              "nip_solve_wall_time_s = " + std::to_string(nip_seconds) + '\n'
          : "";
      write_nip(nonlinear,
                row.nonlinear,
                dir,
                false,
                row.nonlinear.converged
                  ? error_lines(row, parameters) + rolling_text
                  : "");
      if (!rolling_text.empty())
        append_to_summary(dir, rolling_text, nonlinear.communicator());
      contact.write_results(row.nonlinear,
                            dir,
                            number,
                            parameters.output.write_vtu);
      write_nip_pieces(scene, row.nonlinear, dir);
    }

    /// Before the nip of Contact/Values @p target: its solves on the
    /// levels of @p ladder and by the error estimate's @p companion (each
    /// may be absent), each handing its nip over to @p scene; @p guess
    /// gets the first guess of the run's control. Returns why the sweep
    /// stops before the nip (empty: a signal), or nothing.
    std::optional<std::string>
    solve_ahead(Scene                 &scene,
                LevelLadder           *ladder,
                ErrorCompanion        *companion,
                const double           target,
                ErrorCompanion::Guess &guess,
                const MPI_Comm         comm)
    {
      if (ladder)
        {
          const std::string stopped = ladder->solve(target);
          if (!stopped.empty())
            return stopped;
          ladder->hand_over(scene);
        }
      if (companion)
        guess = companion->lead(target, scene);
      // A signal during these solves stops before the nip.
      if ((ladder || companion) && interrupt_requested(comm))
        return std::string();
      return std::nullopt;
    }

    /// Solves the nips of Contact/Values in turn, evaluates and writes
    /// each, and adds the converged ones to @p rows, with their linear
    /// companions if @p linear is given and their error estimates if
    /// @p companion is, each nip solved on the levels of @p ladder first
    /// if it is given; returns why the sweep stopped, empty if it did not.
    std::string
    sweep_nips(Scene                           &scene,
               NipControl                      &control,
               Scene                           *linear_scene,
               ErrorCompanion                  *companion,
               LevelLadder                     *ladder,
               const Parameters::AllParameters &parameters,
               const Parameters::Rolling       *rolling,
               std::vector<NipRow>             &rows)
    {
      const auto        &values = parameters.contact.values;
      const bool         sweep  = values.size() > 1;
      const std::string &top    = parameters.output.directory;
      // The sweep as one ParaView time series per theory; a single nip too
      // (its PVD holds the indenter and contact pressure, solution.pvd not).
      const std::string meaning = sweep_time_meaning(parameters);
      SweepPvd          pvd(top + "/solution_sweep.pvd", meaning);
      SweepPvd          linear_pvd(top + "/solution_sweep_linear.pvd", meaning);
      const bool        series = parameters.output.write_vtu;
      const MPI_Comm    comm   = scene.roll().communicator();
      remove_stale_nips(top, sweep ? values.size() : 0, comm);
      write_tables(
        rows, linear_scene, parameters, scene.description, ladder, comm);
      for (unsigned int n = 0; n < values.size(); ++n)
        {
          arm_stop_line(n + 1, values.size(), rows.size(), top, comm);
          // The nip's directory, relative to the PVD's and from the cwd.
          const std::string nip =
            sweep ? "nip-" + Utilities::int_to_string(n + 1, 2) : ".";
          const std::string dir = sweep ? top + "/" + nip : top;
          const std::string vtu =
            "/solution-" + Utilities::int_to_string(n + 1, 4) + ".pvtu";
          ErrorCompanion::Guess guess;
          if (const auto stop =
                solve_ahead(scene, ladder, companion, values[n], guess, comm))
            {
              arm_interrupt_line("", "");
              return why_stopped(
                *stop, n + 1, values.size(), rows.size(), comm);
            }
          NipRow          row;
          ThermalCoupling thermal;
          CircleFactor    circle_factor;
          const double    nip_seconds = solve_nip(scene,
                                               control,
                                               parameters,
                                               rolling,
                                               values[n],
                                               guess,
                                               row,
                                               thermal,
                                               circle_factor);
          if (row.nonlinear.converged)
            {
              evaluate_nip(scene, n + 1, row);
              if (companion)
                {
                  row.error = companion->estimate(
                    row, values[n], scene, control.local_slope(values[n]));
                  print_error_estimate(row, n + 1, comm);
                }
              if (rolling && rolling->enabled)
                evaluate_rolling_nip(scene,
                                     parameters,
                                     *rolling,
                                     dir,
                                     thermal,
                                     circle_factor,
                                     row);
            }
          write_nip_files(scene, parameters, row, n + 1, dir, nip_seconds);
          if (series && row.nonlinear.converged)
            add_to_sweep(
              pvd, parameters, scene.description, row.nonlinear, nip, vtu);
          if (!row.nonlinear.converged)
            {
              arm_interrupt_line("", "");
              return why_stopped(
                row.nonlinear.message, n + 1, values.size(), rows.size(), comm);
            }

          if (linear_scene)
            solve_linear_companion(*linear_scene,
                                   scene.description,
                                   parameters,
                                   n,
                                   nip,
                                   vtu,
                                   series ? &linear_pvd : nullptr,
                                   row);
          // A signal has said that this nip is not in the tables.
          arm_interrupt_line("", "");
          if (interrupt_requested(comm))
            return why_stopped("", n + 1, values.size(), rows.size(), comm);
          rows.push_back(row);
          write_tables(
            rows, linear_scene, parameters, scene.description, ladder, comm);
        }
      arm_interrupt_line("", "");
      return "";
    }

    /// The nip widths at the ends of the hardness modulus band for each of
    /// @p rows, by the scaling of BandWidths: the same nip solved by
    /// @p control at P E / E_low and P E / E_high, silently; nan where a
    /// solve fails.
    std::vector<BandWidths>
    solve_band_widths(NipControl                      &control,
                      const std::vector<NipRow>       &rows,
                      const Parameters::AllParameters &parameters)
    {
      const Parameters::Material &m = parameters.material;
      const Hardness::Band        e =
        Hardness::modulus_band(m.surface_hardness,
                               Hardness::scale_from_string(m.hardness_scale));
      const double E        = m.hardness_modulus;
      auto         width_at = [&](const NipRow &row, const double modulus) {
        if (modulus == E)
          return 2 * row.nonlinear.half_chord;
        ContactResult r;
        try
          {
            SilenceStream quiet(std::cout);
            r = control.solve(row.nonlinear.nip_load * E / modulus);
          }
        catch (const std::exception &error)
          {
            if (is_local_error(error))
              throw;
          }
        return r.converged ? 2 * r.half_chord
                                   : std::numeric_limits<double>::quiet_NaN();
      };
      std::vector<BandWidths> band;
      for (const NipRow &row : rows)
        {
          BandWidths w;
          w.at_low_modulus  = width_at(row, e.low);
          w.at_high_modulus = width_at(row, e.high);
          band.push_back(w);
        }
      return band;
    }

    /// The nip characteristic and report of @p rows, which also go to
    /// @p rows_out if given; returns the exit code (1, said, if the sweep
    /// stopped for @p failure).
    int
    finish_sweep(const std::vector<NipRow>       &rows,
                 const bool                       with_linear,
                 const std::string               &failure,
                 const Parameters::AllParameters &parameters,
                 const SceneDescription          &scene,
                 const std::vector<BandWidths>   &band,
                 std::vector<NipRow>             *rows_out,
                 const MPI_Comm                   communicator)
    {
      const std::string &top = parameters.output.directory;
      write_nip_characteristic(
        rows, with_linear, scene.roll.cover_thickness(), top, communicator);
      write_nip_report(rows, parameters, scene, top, communicator, band);
      if (rows_out)
        *rows_out = rows;
      arm_interrupt_line("", "");
      if (!failure.empty())
        {
          // A signal may have printed the line already.
          if (Utilities::MPI::this_mpi_process(communicator) == 0 &&
              !interrupt_line_printed())
            std::cerr << "rollnip: error: contact: " << failure
                      << files_note(top) << std::endl;
          return 1;
        }
      return 0;
    }
  } // namespace

  NipNumbers
  nip_numbers(const NipRow &row)
  {
    const ContactResult &r = row.nonlinear;
    NipNumbers           v;
    v[NipQuantity::theta0]            = r.theta0 * deg;
    v[NipQuantity::load]              = r.nip_load;
    v[NipQuantity::indentation]       = r.indentation;
    v[NipQuantity::half_chord]        = r.half_chord;
    v[NipQuantity::peak_pressure]     = r.peak_pressure;
    v[NipQuantity::mean_pressure]     = r.nip_load / (2 * r.half_chord);
    v[NipQuantity::bond_sigma_rr]     = row.bond_sigma_rr_min;
    v[NipQuantity::bond_sigma_rtheta] = row.bond_sigma_rtheta_max;
    return v;
  }

  int
  run_nip_study(const Parameters::AllParameters &parameters,
                const MPI_Comm                   communicator,
                std::vector<NipRow>             *rows_out,
                const Parameters::Rolling       *rolling,
                const bool                       guard_rails,
                CoarserLevels                   *coarser)
  {
    std::vector<NipRow>     rows;
    std::vector<BandWidths> band;
    std::string             failure;
    bool                    with_linear = false;
    // The linear companion: same scene, linear theory, same theta0.
    Parameters::AllParameters linear_parameters = parameters;
    linear_parameters.material.theory           = Parameters::Theory::linear;
    linear_parameters.output.print_timing       = false;
    // The scenes (and the companion's) are destroyed inside the handler
    // when something throws, so that their timers do not report on an
    // exception in flight.
    std::unique_ptr<Scene>           scene, linear;
    std::unique_ptr<RecordingSolver> recorder;
    std::unique_ptr<ErrorCompanion>  companion;
    std::unique_ptr<LevelLadder>     ladder;
    try
      {
        scene = std::make_unique<Scene>(parameters, communicator);
        // At level 0 the error estimate's companion is the finer mesh,
        // solved after the run: it takes the run's slopes where it starts
        // from the run's nip (carry_nip(): one process, a rigid counter
        // surface), and nowhere else needs them.
        if (parameters.accuracy.error_estimate &&
            parameters.mesh.global_refinements == 0 &&
            parameters.contact.mode != Parameters::ContactMode::nip_angle &&
            Utilities::MPI::n_mpi_processes(communicator) == 1 &&
            dynamic_cast<InverseContact *>(&scene->nip_solver()))
          recorder = std::make_unique<RecordingSolver>(*scene);
        NipControl control(recorder ? *recorder : scene->nip_solver(),
                           parameters);
        if (parameters.contact.compare_linear)
          linear = std::make_unique<Scene>(linear_parameters, communicator);

        // The error estimate's companion (Accuracy/Error estimate).
        if (parameters.accuracy.error_estimate)
          companion =
            std::make_unique<ErrorCompanion>(parameters, communicator);
        if (companion && recorder)
          companion->follow(*recorder);

        if (coarser)
          ladder =
            std::make_unique<LevelLadder>(parameters, *coarser, communicator);

        failure = sweep_nips(*scene,
                             control,
                             linear.get(),
                             companion.get(),
                             ladder.get(),
                             parameters,
                             rolling,
                             rows);
        // The coarser levels keep the nips the run finished.
        if (ladder && !failure.empty())
          ladder->write_tables(rows.size(), communicator);
        // The modulus band is the constant modulus's (the last nip may
        // have left its cover softened).
        scene->roll().body().materials().set_modulus_factor({});
        if (failure.empty() && band_by_scaling(parameters))
          band = solve_band_widths(control, rows, parameters);
        if (guard_rails && Utilities::MPI::this_mpi_process(communicator) == 0)
          for (unsigned int n = 0; n < rows.size(); ++n)
            warn_outside_validated_range(rows[n], n + 1, scene->description);

        with_linear = static_cast<bool>(linear);
      }
    catch (...)
      {
        arm_interrupt_line("", "");
        for (auto *s : {scene.get(), linear.get()})
          if (s)
            s->silence_timers();
        companion.reset();
        recorder.reset();
        ladder.reset();
        linear.reset();
        scene.reset();
        throw;
      }

    return finish_sweep(rows,
                        with_linear,
                        failure,
                        parameters,
                        scene->description,
                        band,
                        rows_out,
                        communicator);
  }
} // namespace rollnip
