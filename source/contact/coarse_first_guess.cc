#include <deal.II/base/timer.h>

#include <rollnip/contact/coarse_first_guess.h>
#include <rollnip/contact/nip_control.h>
#include <rollnip/output/silence_cerr.h>
#include <rollnip/problem.h>
#include <rollnip/run_errors.h>
#include <rollnip/scene/scene_builder.h>
#include <rollnip/solvers/iteration_controls.h>

#include <algorithm>

#include <memory>

namespace rollnip
{
  namespace
  {
    /// The coarse nip's control tolerance: a tenth of the level-0 mesh's
    /// error in P (about 1 % on the default scene), which is what the
    /// first guess misses by anyway.
    constexpr double coarse_control_tolerance = 1e-3;

    /// The scene of the coarse solve: the mesh at level 0, no files,
    /// no companions, its iterations stopped at the level of its error.
    Parameters::AllParameters
    coarse_parameters(const Parameters::AllParameters &p)
    {
      Parameters::AllParameters c           = p;
      c.mesh.global_refinements             = 0;
      c.mating_roll.mesh.global_refinements = 0;
      c.contact.compare_linear              = false;
      c.output.print_timing                 = false;
      c.output.write_vtu                    = false;
      c.output.write_csv                    = false;
      c.accuracy.error_estimate             = false;
      c.contact.control_tolerance =
        std::max(p.contact.control_tolerance, coarse_control_tolerance);
      c.contact.tolerance =
        std::max(p.contact.tolerance,
                 IterationControls::control_conformity_fraction *
                   coarse_control_tolerance);
      return c;
    }

    /// A scene with the parameters it refers to, which must outlive it.
    struct OwningScene
    {
      OwningScene(const Parameters::AllParameters &p, const MPI_Comm comm)
          : parameters(p)
          , scene(parameters, comm)
      {}
      const Parameters::AllParameters parameters;
      Scene                           scene;
    };
  } // namespace

  bool
  coarse_first_guess_pays(const Parameters::AllParameters &p)
  {
    const bool controlled =
      p.contact.mode == Parameters::ContactMode::load ||
      p.contact.mode == Parameters::ContactMode::indentation;
    // Two covered rolls only for a single target: their P(theta0) depends
    // on the history of the mating roll's refits by about 1e-4, and a
    // changed path to the first nip can leave a later target of a sweep
    // stalled just off the control tolerance (parameters/two_rolls.prm at
    // 60 N/mm).
    return controlled &&
           (!p.mating_roll.covered || p.contact.values.size() == 1) &&
           p.mesh.global_refinements > 0;
  }

  CoarseFirstGuess
  coarse_first_guess(const Parameters::AllParameters &p,
                     const double                     target,
                     const MPI_Comm                   comm)
  {
    CoarseFirstGuess       guess;
    Timer                  timer;
    std::shared_ptr<Scene> scene;
    try
      {
        SilenceStream quiet(std::cout);
        const auto    owner =
          std::make_shared<OwningScene>(coarse_parameters(p), comm);
        scene = std::shared_ptr<Scene>(owner, &owner->scene);
        scene->roll().set_step_log(false);
        NipControl          control(scene->nip_solver(), owner->parameters);
        const ContactResult r = control.solve(target);
        guess.n_solves        = control.n_contact_solves();
        if (r.converged)
          {
            guess.theta     = r.theta0;
            guess.slope     = control.local_slope(target);
            guess.curvature = control.local_curvature();
            guess.scene     = scene;
          }
        else
          {
            guess.failure               = r.message;
            guess.largest_reached       = control.largest_converged();
            guess.largest_reached_theta = control.largest_converged_theta();
          }
      }
    catch (const std::exception &e)
      {
        if (scene)
          scene->silence_timers();
        if (is_local_error(e))
          throw;
        guess.theta   = 0;
        guess.failure = one_line_message(e);
      }
    if (scene)
      scene->silence_timers();
    guess.seconds = timer.wall_time();
    return guess;
  }
} // namespace rollnip
