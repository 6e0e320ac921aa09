#ifndef rollnip_solvers_iteration_controls_h
#define rollnip_solvers_iteration_controls_h

/**
 * The fixed constants of rollnip's iterations, one line of doc each. The
 * tolerances and budgets a user sets are in the .prm (parameters.h); these
 * are the factors of the safeguards, chosen once and kept for all scenes.
 */
namespace rollnip
{
  namespace IterationControls
  {
    // Newton (newton_solver.cc)
    /// Round-off floor of |R_u| in units of epsilon x G x cell size x
    /// sqrt(DoFs); measured floors are about a tenth of it.
    constexpr double round_off_factor = 100;
    /// Armijo constant: a line-search step must cut the merit by this
    /// fraction of the step length.
    constexpr double sufficient_decrease = 1e-4;
    /// Factor by which the line search shortens the step.
    constexpr double line_search_factor = 0.5;
    /// e_R this far below Residual tolerance converges whatever e_u is.
    constexpr double residual_only_convergence = 1e-3;
    /// Newton iterations in a row without decrease that give up the step.
    constexpr unsigned int stuck_iterations = 2;

    // Load stepping (load_stepper.cc)
    /// Factor of the load increment after a failed step.
    constexpr double cutback_factor = 0.5;
    /// Cut-backs between two looks at the load fraction's progress.
    constexpr unsigned int stall_window = 20;
    /// Least progress per window, as a fraction of the load still to go.
    constexpr double stall_progress = 1e-2;
    /// A load fraction this close to 1 is the full load.
    constexpr double full_load_slack = 1e-12;

    // Contact iteration (inverse_contact.cc)
    /// Attempts to carry one pressure update, each closer to the last.
    constexpr unsigned int pressure_attempts = 4;
    /// Bounds and factor of the retried fraction of a pressure update:
    /// just below the fraction carried, at least 0.1, at most 0.5.
    constexpr double retry_min = 0.1, retry_max = 0.5, retry_factor = 0.8;
    /// Halvings in a row of a contact update whose residual grew.
    constexpr unsigned int max_halvings = 4;
    /// A conformity residual changing by less than this fraction after a
    /// halving has stalled.
    constexpr double stalled_residual = 1e-3;
    /// Under load or indentation control, the conformity tolerance is at
    /// most this fraction of Contact/Control tolerance.
    constexpr double control_conformity_fraction = 0.1;
    /// Under load or indentation control a contact solve ends early
    /// (provisional) once its theta0 misses the target by more than
    /// provisional_miss x Contact/Control tolerance and its conformity
    /// residual is below provisional_fraction x that miss: q then carries
    /// an error of about 1 % of the miss, which changes the next secant
    /// step by about as much; the iterate that meets the target is always
    /// converged in full.
    constexpr double provisional_miss = 10, provisional_fraction = 1e-2;
    /// InverseContact::pressure_growth(): the growth d log(peak) /
    /// d log theta0 of the contact pressure's peak between two converged
    /// nips at least min_growth_span apart in log theta0 (nearer, their
    /// conformity error is a good part of the difference), clamped to
    /// [min_pressure_growth, max_pressure_growth] (Hertz: 1).
    constexpr double min_growth_span = 1e-3, min_pressure_growth = 0.5,
                     max_pressure_growth = 3.;
    /// A surface node within this relative distance of theta0 is the edge.
    constexpr double edge_slack = 1e-12;

    /// A contact update whose conformity residual grew is cut by this
    /// factor towards the last accepted one.
    constexpr double halving_factor = 0.5;

    // Load and indentation control (nip_control.cc)
    /// Slopes of log q against log theta0 allowed to the secant: P rises
    /// like theta0^2 (Hertz) to theta0^5 (thin layer), u0 like theta0^2;
    /// the bounds only catch a secant through two nearly equal points.
    constexpr double min_slope = 0.5, max_slope = 10.;
    /// NipControl::local_slope() takes its second nip at least this many
    /// times Contact/Control tolerance from the first in log q (where the
    /// conformity error of q, a tenth of the tolerance, errs the slope by
    /// 1e-3 at most), and at most max_slope_spread (beyond, the curve's
    /// bend errs it by a few per cent).
    constexpr double slope_spread_of_tolerance = 100, max_slope_spread = 0.05;
    /// The slope assumed while one nip has converged: between Hertz and
    /// the thin layer for P, the geometric overlap for u0.
    constexpr double default_slope_load = 3., default_slope_indentation = 2.;
    /// The first nip of a load target is this fraction of the smaller of
    /// the Hertz and thin-layer widths (both too wide for a finite cover).
    constexpr double first_guess_fraction = 0.7;
    /// The first guess keeps sin(theta0) below this (the nip stays on the
    /// front of the roll).
    constexpr double max_first_guess_sine = 0.9;
    /// A nip joins the interpolation nodes only if its q differs from the
    /// nodes' by this fraction of the log-distance to the target.
    constexpr double node_spread = 0.3;
    /// One step of theta0 at most multiplies or divides it by this factor;
    /// the inverse quadratic beyond it is replaced by the power law.
    constexpr double max_step_factor = 2.;
    /// A theta0 this close (relative) above a converged one that still
    /// fails means the cover cannot carry more.
    constexpr double step_back_resolution = 1e-2;
    /// A theta0 whose contact solve failed from a state far from it (a
    /// cold start) is tried again from the converged nips once they come
    /// within this fraction of it, at most max_failed_retries times per
    /// target: a stiff thin coat fails from the undeformed state at a nip
    /// it reaches from a smaller one.
    constexpr double       failed_retry_fraction = 0.5;
    constexpr unsigned int max_failed_retries    = 6;

    // Two covered rolls (two_roll_contact.cc)
    /// The mating roll's first nip angle keeps its sine below this.
    constexpr double max_mate_sine = 0.95;
    /// The passes end when the mating surface moves less than this many
    /// times the contact iteration's conformity tolerance (times u0): below
    /// it, the change is the inner iterations' own noise.
    constexpr double two_roll_tolerance_factor = 10;
    /// Bounds of Aitken's relaxation factor.
    constexpr double relaxation_min = 0.05, relaxation_max = 1;
    /// The mating roll's nip-fitted mesh is refitted when its contact edge
    /// lies off the fitted node by more than this fraction of the angle.
    constexpr double mate_refit_tolerance = 1e-3;
    /// Refits per two-roll solve at most (each costs a few passes).
    constexpr unsigned int max_mate_refits = 4;
  } // namespace IterationControls
} // namespace rollnip

#endif
