#include <deal.II/base/mpi.h>

#include <rollnip/contact/coarse_first_guess.h>
#include <rollnip/contact/nip_control.h>
#include <rollnip/contact/nip_estimates.h>
#include <rollnip/interrupt.h>
#include <rollnip/material/material_table.h>
#include <rollnip/scene/scene_builder.h>
#include <rollnip/solvers/iteration_controls.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>

namespace rollnip
{
  namespace
  {
    constexpr double deg = 180. / numbers::PI;

    /// A cold target more than this far above the largest q the level-0
    /// scene reached before it failed is out of reach on any mesh: the
    /// levels differ in q(theta0) by a few per cent, and in the load a
    /// cover carries before it would invert by about as much.
    constexpr double coarse_reach_fraction = 0.5;
    /// Stepping back from failed contact solves ends below this fraction
    /// of the first theta0 tried (ten halvings): a nip that small is not
    /// what the target needs, and the mesh would not resolve it.
    constexpr double min_step_back = 1e-3;
    /// The curvature of log theta0 in log q is taken from three nips at
    /// least this far apart in log q: their q carry the conformity error
    /// of the level-0 control (about 1e-4), which the second divided
    /// difference divides by the product of the gaps.
    constexpr double min_curvature_spread = 0.02;

    /// While the control iterates, solves at a theta0 far from the target
    /// may stop early (provisional) if @p allowed; the goal is cleared on
    /// every way out.
    class GoalScope
    {
    public:
      GoalScope(NipSolver                    &solver,
                const bool                    allowed,
                const NipSolver::ControlGoal &goal)
          : solver(solver)
      {
        if (allowed)
          solver.set_control_goal(goal);
      }
      ~GoalScope()
      {
        solver.set_control_goal(std::nullopt);
      }
      GoalScope(const GoalScope &) = delete;
      GoalScope &
      operator=(const GoalScope &) = delete;

    private:
      NipSolver &solver;
    };

    /// Marks the message of a contact solve that stalled on round-off
    /// (InverseContact::damp()).
    const std::string stalled_on_round_off = "stalled on round-off";

    /// The first solve on the run's mesh starts from the level-0 nip of
    /// the first guess, its state carried over (the meshes nest at the
    /// same theta0), rather than from the unloaded cover: a few Newton
    /// steps instead of a load ramp.
    void
    start_from_coarse(NipSolver &fine, Scene &coarse)
    {
      auto *mine   = dynamic_cast<InverseContact *>(&fine);
      auto *theirs = dynamic_cast<InverseContact *>(&coarse.nip_solver());
      if (mine && theirs)
        mine->start_from(*theirs);
    }

    /// Why a target is not reached when the contact solve failed at every
    /// theta0 from @p first down to @p last [rad], the last for @p why.
    std::string
    every_theta_failed(const double       first,
                       const double       last,
                       const std::string &why)
    {
      std::ostringstream s;
      s << std::setprecision(4)
        << "the contact iteration fails at every theta0 "
        << "tried, from " << first * deg << " down to " << last * deg
        << " deg (the last: " << why << ")";
      return s.str();
    }

    /// Why a target is out of reach when the contact solve failed at
    /// @p theta [rad] for @p why, and even the steepest rise of the
    /// @p quantity below it falls short.
    std::string
    steepest_rise_short(const double       theta,
                        const std::string &quantity,
                        const std::string &why)
    {
      std::ostringstream s;
      s << std::setprecision(6)
        << "the contact iteration fails at theta0 = " << theta * deg
        << " deg, and below it even the steepest rise of " << quantity
        << " with theta0 falls short (" << why << ")";
      return s.str();
    }

    /// Why the iteration on theta0 ended without meeting its target:
    /// @p closest is the nearest relative miss of a converged nip (inf if
    /// none converged), @p last the last failed solve's message.
    std::string
    stall_reason(const double               closest,
                 const std::string         &quantity,
                 const Parameters::Contact &c,
                 const std::string         &last)
    {
      std::ostringstream why;
      why << std::setprecision(3);
      if (std::isfinite(closest))
        why << "the iteration on theta0 stalled at |" << quantity
            << " / target - 1| = " << closest << " (Contact/Control tolerance "
            << c.control_tolerance << ") after " << c.max_iterations
            << " contact solves (Contact/Maximum iterations): raise either";
      else
        why << "no contact solve converged in the " << c.max_iterations
            << " of Contact/Maximum iterations (the last: " << last << ")";
      return why.str();
    }
  } // namespace

  NipControl::NipControl(NipSolver &contact, const Parameters::AllParameters &p)
      : contact(contact)
      , parameters(p)
      , by_load(p.contact.mode == Parameters::ContactMode::load)
  {}

  double
  NipControl::controlled(const ContactResult &r) const
  {
    return by_load ? r.nip_load : r.indentation;
  }

  double
  NipControl::first_guess(const double target) const
  {
    const double R0 = parameters.geometry.outer_radius;
    const double R  = NipEstimates::effective_radius(contact.scene());
    double       b;
    if (by_load)
      {
        // Hertz (E* = 4 G) and the thin layer give too wide a nip for a
        // bonded layer of finite thickness: start below both.
        const double b_hertz = std::sqrt(
          4 * target * R /
          (numbers::PI * NipEstimates::contact_modulus(contact.scene())));
        const double b_thin =
          std::pow(7.5 * R *
                     NipEstimates::thin_layer_compliance(contact.scene()) *
                     target,
                   0.2);
        b = IterationControls::first_guess_fraction * std::min(b_hertz, b_thin);
      }
    else
      b = std::sqrt(2 * R * target); // the chord of the geometric overlap
    return std::asin(std::min(b / R0, IterationControls::max_first_guess_sine));
  }

  double
  NipControl::cold_guess(const double target)
  {
    if (!coarse_first_guess_pays(parameters))
      return first_guess(target);
    const CoarseFirstGuess c =
      coarse_first_guess(parameters, target, contact.communicator());
    n_coarse += c.n_solves;
    ConditionalOStream pcout(
      std::cout, Utilities::MPI::this_mpi_process(contact.communicator()) == 0);
    if (c.theta > 0)
      {
        slope_hint     = c.slope;
        curvature_hint = c.curvature;
        hint_target    = target;
        start_from_coarse(contact, *c.scene);
        pcout << "First guess from mesh level 0: theta0 = " << std::fixed
              << std::setprecision(6) << c.theta * deg << " deg (" << c.n_solves
              << " coarse contact solves, " << std::setprecision(3) << c.seconds
              << " s)" << std::endl;
        return c.theta;
      }
    if (c.largest_reached > 0 &&
        c.largest_reached < coarse_reach_fraction * target)
      {
        // The level-0 nip differs from this mesh's by its discretisation
        // error, a few per cent: the solves that would find the same limit
        // here fail slowly, each after many load-step cutbacks.
        std::ostringstream s;
        s << std::setprecision(6) << "on mesh level 0 the largest "
          << quantity() << " reached is " << c.largest_reached << unit()
          << " at theta0 = " << c.largest_reached_theta * deg
          << " deg before the search stopped, less than "
          << coarse_reach_fraction * 100 << " % of the target";
        coarse_refusal = s.str();
      }
    pcout << "No first guess from mesh level 0 (" << c.failure
          << "): starting from Hertz and the thin layer" << std::endl;
    return first_guess(target);
  }

  double
  NipControl::local_slope(const double target) const
  {
    const std::vector<Point> near = nearest_first(target);
    if (near.size() < 2)
      return 0;
    // The last iterates of a target lie within the control tolerance of
    // each other, where the conformity error of q is a good part of their
    // difference; a provisional q is off by about 1 % of its miss.
    const double min_spread = IterationControls::slope_spread_of_tolerance *
                              parameters.contact.control_tolerance;
    const Point *partner = &near[1];
    for (std::size_t i = 1; i < near.size(); ++i)
      {
        const double spread = std::abs(std::log(near[i].q / near[0].q));
        if (spread > IterationControls::max_slope_spread)
          break;
        if (!near[i].provisional && spread >= min_spread)
          {
            partner = &near[i];
            break;
          }
      }
    if (near[0].theta == partner->theta)
      return 0;
    const double slope = std::log(near[0].q / partner->q) /
                         std::log(near[0].theta / partner->theta);
    return std::isfinite(slope) && slope > 0 ? slope : 0;
  }

  double
  NipControl::local_curvature() const
  {
    if (converged.size() < 3)
      return 0;
    // The lowest and highest q and the nip nearest their middle (log q).
    const auto [low, high] =
      std::minmax_element(converged.begin(),
                          converged.end(),
                          [](const auto &a, const auto &b) {
                            return a.q < b.q;
                          });
    const double x_low = std::log(low->q), x_high = std::log(high->q);
    const double middle = 0.5 * (x_low + x_high);
    const Point *mid    = nullptr;
    for (const auto &p : converged)
      if (&p != &*low && &p != &*high &&
          (mid == nullptr || std::abs(std::log(p.q) - middle) <
                               std::abs(std::log(mid->q) - middle)))
        mid = &p;
    if (mid == nullptr)
      return 0;
    const double x_mid = std::log(mid->q);
    const double gap   = min_curvature_spread;
    if (x_mid - x_low < gap || x_high - x_mid < gap)
      return 0;
    // Twice the second divided difference of log theta0 in log q.
    const double left  = std::log(mid->theta / low->theta) / (x_mid - x_low);
    const double right = std::log(high->theta / mid->theta) / (x_high - x_mid);
    const double c     = 2 * (right - left) / (x_high - x_low);
    return std::isfinite(c) ? c : 0;
  }

  std::vector<NipControl::Point>
  NipControl::nearest_first(const double target) const
  {
    std::vector<Point> near = converged;
    std::sort(near.begin(), near.end(), [target](const auto &a, const auto &b) {
      return std::abs(std::log(a.q / target)) <
             std::abs(std::log(b.q / target));
    });
    return near;
  }

  double
  NipControl::secant_guess(const double target) const
  {
    Assert(!converged.empty(), ExcInternalError());
    const std::vector<Point> near = nearest_first(target);
    const double             default_slope =
      by_load ? IterationControls::default_slope_load
                          : IterationControls::default_slope_indentation;
    const bool hinted     = slope_hint > 0 && target == hint_target;
    double     slope      = hinted ? slope_hint : default_slope;
    const bool two_points = near.size() > 1 && near[0].theta != near[1].theta &&
                            !(hinted && n_at_target < 2);
    if (two_points)
      slope = std::log(near[0].q / near[1].q) /
              std::log(near[0].theta / near[1].theta);
    if (!std::isfinite(slope))
      slope = default_slope;
    slope = std::clamp(slope,
                       IterationControls::min_slope,
                       IterationControls::max_slope);
    const double power_law =
      near[0].theta * std::pow(target / near[0].q, 1. / slope);
    // The two nips of a cold target: the level-0 curve's bend turns the
    // secant in log-log into the parabola through both with that
    // curvature (the thin cover's log P against log theta0 bends enough
    // to cost a fourth solve otherwise).
    if (two_points && converged.size() == 2 && target == hint_target &&
        curvature_hint != 0)
      {
        const double x = std::log(target);
        return power_law *
               std::exp(0.5 * curvature_hint * (x - std::log(near[0].q)) *
                        (x - std::log(near[1].q)));
      }
    return power_law;
  }

  double
  NipControl::predict(const double target) const
  {
    Assert(!converged.empty(), ExcInternalError());
    // A slope given for this target beats a quadratic through the nips
    // of earlier targets while one nip of it has converged.
    if (slope_hint > 0 && target == hint_target && n_at_target < 2)
      return secant_guess(target);
    const std::vector<Point> near = nearest_first(target);
    // The nearest nip, and up to two more whose q differ from those taken
    // by a good part of the distance to the target: the iterates of an
    // earlier target lie too close together to give a curvature.
    const double       reach = std::abs(std::log(target / near[0].q));
    std::vector<Point> nodes = {near[0]};
    for (std::size_t i = 1; i < near.size() && nodes.size() < 3; ++i)
      if (std::all_of(nodes.begin(), nodes.end(), [&](const Point &n) {
            return std::abs(std::log(near[i].q / n.q)) >
                   IterationControls::node_spread * reach;
          }))
        nodes.push_back(near[i]);
    if (nodes.size() < 3)
      return secant_guess(target);
    // Inverse quadratic interpolation: log theta0 as a quadratic in log q.
    const double x     = std::log(target);
    double       log_t = 0;
    for (std::size_t a = 0; a < 3; ++a)
      {
        double l = 1;
        for (std::size_t b = 0; b < 3; ++b)
          if (b != a)
            l *= (x - std::log(nodes[b].q)) /
                 (std::log(nodes[a].q) - std::log(nodes[b].q));
        log_t += l * std::log(nodes[a].theta);
      }
    const double theta = std::exp(log_t);
    // Far outside its nodes a quadratic may turn over: then the power law.
    const double power_law = secant_guess(target);
    const double f         = IterationControls::max_step_factor;
    return std::isfinite(theta) && theta > power_law / f &&
               theta < f * power_law
             ? theta
             : power_law;
  }

  double
  NipControl::next_theta(const double target,
                         const double theta,
                         const double upper) const
  {
    // The secant (or inverse quadratic), kept inside the bracket of
    // converged nips around the target and below @p upper.
    double lo = 0, hi = upper;
    for (const auto &p : converged)
      if (p.q < target)
        lo = std::max(lo, p.theta);
      else
        hi = std::min(hi, p.theta);
    const double f    = IterationControls::max_step_factor;
    double       next = std::clamp(predict(target), theta / f, f * theta);
    if (!(next > lo && next < hi))
      next = lo > 0 ? 0.5 * (lo + hi) : 0.5 * hi;
    return std::min(next, upper);
  }

  bool
  NipControl::beyond_steepest_rise(const double target,
                                   const double failed) const
  {
    // q rises like theta0^2 (Hertz) to theta0^5 (thin layer); the
    // secant's largest slope bounds what lies between the last converged
    // nip and the failed theta0.
    const double below = converged_below(failed);
    for (const auto &p : converged)
      if (p.theta == below)
        return p.q * std::pow(failed / below, IterationControls::max_slope) <
               target;
    return false;
  }

  double
  NipControl::largest_converged() const
  {
    double q = 0;
    for (const auto &p : converged)
      q = std::max(q, p.q);
    return q;
  }

  double
  NipControl::largest_converged_theta() const
  {
    double q = 0, theta = 0;
    for (const auto &p : converged)
      if (p.q > q)
        {
          q     = p.q;
          theta = p.theta;
        }
    return theta;
  }

  std::string
  NipControl::quantity() const
  {
    return by_load ? "P" : "u0";
  }

  std::string
  NipControl::unit() const
  {
    return by_load ? " N/mm" : " mm";
  }

  std::string
  NipControl::largest_reached() const
  {
    std::ostringstream s;
    s << std::setprecision(6);
    if (converged.empty())
      s << "no nip converged";
    else
      s << "the largest " << quantity() << " reached is " << converged.back().q
        << unit() << " at theta0 = " << converged.back().theta * deg << " deg";
    return s.str();
  }

  ContactResult
  NipControl::refuse(ContactResult      r,
                     const double       target,
                     const std::string &why) const
  {
    std::ostringstream s;
    s << std::setprecision(6) << "the target " << quantity() << " = " << target
      << unit() << " is out of reach: " << why << "; " << largest_reached();
    r.converged = false;
    r.message   = s.str();
    return r;
  }

  ContactResult
  NipControl::stop_short(ContactResult      r,
                         const double       target,
                         const std::string &why) const
  {
    std::ostringstream s;
    s << std::setprecision(6) << "the target " << quantity() << " = " << target
      << unit() << " is not reached: " << why << "; " << largest_reached();
    r.converged = false;
    r.message   = s.str();
    return r;
  }

  double
  NipControl::converged_below(const double theta) const
  {
    double below = 0;
    for (const auto &p : converged)
      if (p.theta < theta)
        below = p.theta;
    return below;
  }

  void
  NipControl::remember(const double theta,
                       const double q,
                       const bool   provisional)
  {
    converged.insert(std::upper_bound(converged.begin(),
                                      converged.end(),
                                      theta,
                                      [](const double t, const Point &p) {
                                        return t < p.theta;
                                      }),
                     Point{theta, q, provisional});
  }

  std::string
  NipControl::beyond_mesh(const double theta_max) const
  {
    std::ostringstream s;
    s << std::setprecision(6) << "theta0 would pass " << theta_max * deg
      << " deg, the largest nip this mesh takes"
      << (contact.max_nip_angle() > 0 ? " (half the sector angle on "
                                        "the nip-fitted mesh)"
                                      : "");
    return s.str();
  }

  ContactResult
  NipControl::solve(const double target,
                    const double guess,
                    const double guess_slope)
  {
    const auto &c = parameters.contact;
    if (c.mode == Parameters::ContactMode::nip_angle)
      {
        ++n_solves;
        return contact.solve(target);
      }
    const MPI_Comm     comm = contact.communicator();
    ConditionalOStream pcout(std::cout,
                             Utilities::MPI::this_mpi_process(comm) == 0);
    const double       theta_max = contact.max_nip_angle();

    double theta = guess > 0           ? guess
                   : converged.empty() ? cold_guess(target)
                                       : predict(target);
    theta        = std::min(theta, theta_max);
    n_at_target  = 0;
    if (guess > 0 && guess_slope > 0)
      {
        slope_hint     = guess_slope;
        curvature_hint = 0;
        hint_target    = target;
      }
    const double  first_theta = theta;
    double        failed_at   = std::numeric_limits<double>::max();
    unsigned int  n_retries   = 0;
    double        closest     = std::numeric_limits<double>::infinity();
    ContactResult r;
    if (!coarse_refusal.empty())
      return refuse(r, target, std::exchange(coarse_refusal, std::string()));
    const GoalScope goal(contact,
                         provisional_allowed,
                         {by_load, target, c.control_tolerance});
    for (unsigned int it = 1; it <= c.max_iterations; ++it)
      {
        if (it > 1 && interrupt_requested(comm))
          {
            r.converged = false;
            r.message   = interrupt_message();
            return r;
          }
        ++n_solves;
        r = contact.solve(theta);
        if (!r.converged)
          {
            // Round-off, not the physics: no other theta0 does better.
            if (r.message.find(stalled_on_round_off) != std::string::npos)
              return stop_short(r, target, r.message);
            const double below = converged_below(theta);
            failed_at          = std::min(failed_at, theta);
            if (theta - below < IterationControls::step_back_resolution * theta)
              return refuse(r,
                            target,
                            "the contact iteration fails for every theta0 "
                            "just above the largest converged one (" +
                              r.message + ")");
            if (beyond_steepest_rise(target, theta))
              return refuse(r,
                            target,
                            steepest_rise_short(theta, quantity(), r.message));
            const double next = below > 0 ? 0.5 * (below + theta) : 0.5 * theta;
            if (next < min_step_back * first_theta)
              return stop_short(
                r, target, every_theta_failed(first_theta, theta, r.message));
            pcout << "Outer iteration " << it << ": theta0 = " << std::fixed
                  << std::setprecision(6) << theta * deg << " deg failed ("
                  << r.message << "); stepping back" << std::endl;
            theta = next;
            continue;
          }
        const double q = controlled(r);
        n_provisional += r.provisional;
        remember(theta, q, r.provisional);
        ++n_at_target;
        pcout << "Outer iteration " << it << ": theta0 = " << std::fixed
              << std::setprecision(6) << theta * deg << " deg gives "
              << quantity() << " = " << q << unit() << " (target " << target
              << ")" << (r.provisional ? " (provisional)" : "") << std::endl;
        closest = std::min(closest, std::abs(q / target - 1));
        if (!r.provisional && std::abs(q / target - 1) < c.control_tolerance)
          return r;
        if (q < target && theta >= theta_max * (1 - 1e-12))
          return refuse(r, target, beyond_mesh(theta_max));
        // Approach a failed theta0 from this converged nip rather than
        // bisect towards it for good.
        if (q < target && n_retries < IterationControls::max_failed_retries &&
            theta >= IterationControls::failed_retry_fraction * failed_at)
          {
            failed_at = std::numeric_limits<double>::max();
            ++n_retries;
          }
        theta = next_theta(target, theta, std::min(failed_at, theta_max));
      }
    return stop_short(r,
                      target,
                      stall_reason(closest, quantity(), c, r.message));
  }

  ContactResult
  solve_controlled_nip(NipSolver                       &contact,
                       const Parameters::AllParameters &parameters,
                       const double                     target)
  {
    NipControl control(contact, parameters);
    return control.solve(target);
  }
} // namespace rollnip
