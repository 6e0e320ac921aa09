#include <deal.II/base/mpi.h>

#include <rollnip/body/nested_transfer.h>
#include <rollnip/boundary_ids.h>
#include <rollnip/contact/inverse_contact.h>
#include <rollnip/contact/nip_estimates.h>
#include <rollnip/geometry/angles.h>
#include <rollnip/material/material_table.h>
#include <rollnip/output/atomic_file.h>
#include <rollnip/problem.h>
#include <rollnip/solvers/iteration_controls.h>
#include <rollnip/solvers/tolerance_floor.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <sstream>

namespace rollnip
{
  namespace
  {
    /// Hat function k on the knots t, with f(t.back()) = 0. Piecewise
    /// linear, except on the last segment, where it falls like the square
    /// root of the distance to the edge: the pressure at the edge of a
    /// smooth (non-conforming) contact does so, and the linear shape there
    /// made the load depend on where theta0 falls between two nodes.
    double
    hat(const std::vector<double> &t, const unsigned int k, const double x)
    {
      // A node within round-off of the edge is the edge (as in solve()):
      // the square root would turn that round-off into a pressure.
      if (x < 0 || x >= t.back() * (1 - 1e-12))
        return 0;
      if (k > 0 && x >= t[k - 1] && x <= t[k])
        return (x - t[k - 1]) / (t[k] - t[k - 1]);
      if (x >= t[k] && x <= t[k + 1])
        return (k + 2 == t.size())
                 ? std::sqrt((t[k + 1] - x) / (t[k + 1] - t[k]))
                 : (t[k + 1] - x) / (t[k + 1] - t[k]);
      return 0;
    }

    /// f(x) = sum_k a_k hat_k(x).
    double
    interpolate(const std::vector<double> &t,
                const std::vector<double> &a,
                const double               x)
    {
      double f = 0;
      for (unsigned int k = 0; k < a.size(); ++k)
        f += a[k] * hat(t, k, x);
      return f;
    }
  } // namespace

  InverseContact::InverseContact(ContactBody                     &body,
                                 const Parameters::AllParameters &parameters)
      : InverseContact(body, parameters, describe_scene(parameters), nullptr)
  {}

  InverseContact::InverseContact(
    ContactBody                          &body,
    const Parameters::AllParameters      &parameters,
    const SceneDescription               &description,
    std::shared_ptr<const CounterSurface> counter_surface)
      : body(body)
      , parameters(parameters)
      , description(description)
      , counter_surface(counter_surface ? std::move(counter_surface)
                                        : make_counter_surface(description))
      , pcout(std::cout,
              Utilities::MPI::this_mpi_process(body.communicator()) == 0)
      , conformity_tolerance(
          parameters.contact.mode == Parameters::ContactMode::nip_angle
            ? parameters.contact.tolerance
            : std::min(parameters.contact.tolerance,
                       IterationControls::control_conformity_fraction *
                         parameters.contact.control_tolerance))
  {}

  void
  InverseContact::collect_surface_nodes()
  {
    nodes = body.surface_nodes();
  }

  std::vector<Tensor<1, dim>>
  InverseContact::nodal_values(const TrilinosWrappers::MPI::Vector &v) const
  {
    std::vector<Tensor<1, dim>> u =
      surface_values(nodes, v, body.locally_owned());
    // Linear theory measures the gap at the reference point along its
    // normal (doc/intro.md eq. 7.3): the tangential displacement moves no
    // point into or away from the indenter. It is not small next to the
    // nip in thin covers, where keeping it would mix a geometric
    // nonlinearity into the linear theory.
    if (parameters.material.theory == Parameters::Theory::linear)
      for (unsigned int i = 0; i < nodes.size(); ++i)
        {
          const Tensor<1, dim> normal = nodes[i].X / nodes[i].X.norm();
          u[i]                        = (u[i] * normal) * normal;
        }
    return u;
  }

  double
  InverseContact::max_nip_angle()
  {
    if (body.has_nip_fitted_mesh())
      return body.max_nip_angle();
    if (nodes.empty())
      collect_surface_nodes();
    // The edge row needs two free nodes beyond the zone.
    return nodes.size() > 3 ? nodes[nodes.size() - 3].theta : 0.;
  }

  unsigned int
  nodes_in_zone(const std::vector<SurfaceNode> &nodes, const double theta0)
  {
    unsigned int m = 0;
    while (m < nodes.size() &&
           nodes[m].theta < theta0 * (1 - IterationControls::edge_slack))
      ++m;
    AssertThrow(m + 1 < nodes.size(),
                ExcMessage("Contact: the contact zone reaches the end of the "
                           "outer arc"));
    AssertThrow(m >= 2,
                ExcMessage("Contact/Half nip angle is too small for the mesh: "
                           "refine near theta = 0 (at least two surface nodes "
                           "must lie in the contact zone)"));
    return m;
  }

  InverseContact::Zone
  InverseContact::make_zone(const double theta0)
  {
    // On the nip-fitted mesh the contact edge is moved onto a node.
    if (body.has_nip_fitted_mesh())
      {
        body.fit_mesh_to_nip(theta0);
        nodes.clear();
      }
    if (nodes.empty())
      collect_surface_nodes();
    AssertThrow(nodes.size() > 2 && std::abs(nodes[0].theta) < 1e-12,
                ExcMessage("the outer surface has no node on the line of "
                           "centres (R0, 0)"));

    // Knots: the nodes below theta0, then theta0 itself (f = 0 there).
    // Every knot but the first carries a zero-gap equation, and so does
    // theta0, so that every node of the zone is held on the indenter. A
    // node within round-off of theta0 is the edge (always so on the
    // nip-fitted mesh).
    Zone zone;
    zone.theta0 = theta0;
    zone.m      = nodes_in_zone(nodes, theta0);
    for (unsigned int k = 0; k < zone.m; ++k)
      zone.knots.push_back(nodes[k].theta);
    zone.knots.push_back(theta0);

    // Where theta0 falls between two nodes, for its interpolated position.
    zone.above       = zone.m; // the first node beyond theta0
    zone.left        = zone.above - 1;
    zone.B           = zone.above + 1;
    const double t_A = nodes[zone.above].theta, t_B = nodes[zone.B].theta;
    zone.weight = std::min(1.,
                           (theta0 - nodes[zone.left].theta) /
                             (t_A - nodes[zone.left].theta));
    // The edge row: beyond a smooth contact edge the gap grows like
    // (theta - theta0)^(3/2), so the gaps of the first two free nodes A =
    // above and B satisfy
    //   g_A (theta_B - theta0)^(3/2) - g_B (theta_A - theta0)^(3/2) = 0.
    // At theta0 = theta_A it reads g_A = 0. When theta0 passes a node, the
    // node joins the zone with its own pressure value, so P jumps by an
    // amount of the order of the discretisation error on a fixed mesh
    // (doc/intro.md section 7); the nip-fitted mesh has no jumps.
    zone.c_A = std::pow(std::max(0., t_B - theta0) / (t_B - t_A), 1.5);
    zone.c_B = std::pow(std::max(0., t_A - theta0) / (t_B - t_A), 1.5);
    return zone;
  }

  void
  InverseContact::initial_pressure(const Zone &zone, Iterate &iterate) const
  {
    // A Hertz-like parabola with the peak pressure E* b / (2 R) of two
    // cylinders (the mating one rigid or covered).
    const double half_width =
      parameters.geometry.outer_radius * std::sin(zone.theta0);
    const double p_hertz = NipEstimates::contact_modulus(description) *
                           half_width /
                           (2 * NipEstimates::effective_radius(description));
    const double growth = pressure_growth();
    iterate.a.assign(zone.m, 0.);
    iterate.f_from.assign(zone.m, 0.);
    for (unsigned int k = 0; k < zone.m; ++k)
      {
        const double t = zone.knots[k];
        if (applied_pressure)
          {
            // Warm start from the pressure of the current state, stretched
            // to the new zone and scaled as the peak grew between the last
            // two nips (as in Hertz, peak ~ nip width, before there are
            // two): a cover thinner than the nip stiffens as it grows.
            iterate.f_from[k] = applied_pressure(t);
            iterate.a[k] = applied_pressure(t * applied_theta0 / zone.theta0) *
                           std::pow(zone.theta0 / applied_theta0, growth);
          }
        else
          iterate.a[k] =
            p_hertz * std::sqrt(std::max(0., 1 - std::pow(t / zone.theta0, 2)));
      }
  }

  std::string
  InverseContact::carry_pressure(const Zone        &zone,
                                 Iterate           &iterate,
                                 const unsigned int it)
  {
    using namespace IterationControls;
    TrilinosWrappers::MPI::Vector saved(body.owned_solution());
    std::string                   why;
    for (unsigned int attempt = 0; attempt < pressure_attempts; ++attempt)
      {
        saved                                     = body.current_solution();
        const std::function<double(double)> from  = applied_pressure;
        const std::vector<double>           to    = iterate.a;
        const std::vector<double>           knots = zone.knots;
        body.set_pressure(
          [knots, from, to](const double theta, const double lambda) {
            const double f0 = from ? from(theta) : 0.;
            return f0 + lambda * (interpolate(knots, to, theta) - f0);
          });
        // From a converged contact state the change is small: try the
        // whole update in one step (cut back if needed).
        const RunStatus status =
          applied_pressure ? body.run(true, 1.) : body.run(false);
        if (status.converged)
          return "";
        why = status.message;
        body.set_solution(saved);
        if (!applied_pressure)
          return "the cover cannot carry the first pressure guess (" + why +
                 ")";
        // The run carried the fraction status.load_fraction of the update:
        // retry just below it.
        const double factor =
          status.load_fraction > 0
            ? std::min(retry_max,
                       std::max(retry_min, retry_factor * status.load_fraction))
            : retry_max;
        for (unsigned int k = 0; k < zone.m; ++k)
          iterate.a[k] =
            iterate.f_from[k] + factor * (iterate.a[k] - iterate.f_from[k]);
      }
    return "the cover cannot carry the pressure update of contact iteration " +
           std::to_string(it) + ", even reduced " +
           std::to_string(pressure_attempts - 1) + " times (" + why + ")";
  }

  InverseContact::Gaps
  InverseContact::measure_gaps(const Zone &zone, ContactResult &result) const
  {
    const auto U = nodal_values(body.current_solution());
    Gaps       gaps;
    gaps.u0 = -U[0][0];
    for (unsigned int i = 0; i < nodes.size(); ++i)
      gaps.x.emplace_back(nodes[i].X + U[i]);
    const double     u0 = gaps.u0;
    const auto      &x  = gaps.x;
    const auto      &cs = *counter_surface;
    const Point<dim> x_theta0((1 - zone.weight) * x[zone.left] +
                              zone.weight * x[zone.above]);
    // Zero gap at the nodes 1..m-1 of the zone, and the edge row.
    gaps.g.resize(zone.m);
    for (unsigned int j = 1; j < zone.m; ++j)
      gaps.g[j - 1] = cs.gap(x[j], u0) / u0;
    gaps.g[zone.m - 1] = (zone.c_A * cs.gap(x[zone.above], u0) -
                          zone.c_B * cs.gap(x[zone.B], u0)) /
                         u0;
    gaps.conformity = 0;
    gaps.residual   = std::abs(gaps.g[zone.m - 1]);
    for (unsigned int j = 0; j + 1 < zone.m; ++j)
      {
        gaps.conformity = std::max(gaps.conformity, std::abs(gaps.g[j]));
        gaps.residual   = std::max(gaps.residual, std::abs(gaps.g[j]));
      }
    double min_gap_outside = std::numeric_limits<double>::max();
    for (unsigned int i = zone.above; i < nodes.size(); ++i)
      min_gap_outside = std::min(min_gap_outside, cs.gap(x[i], u0));

    // The deformed contact arc from the line of centres to theta0.
    result.half_arc = 0;
    for (unsigned int i = 1; i <= zone.left; ++i)
      result.half_arc += x[i].distance(x[i - 1]);
    result.half_arc += x_theta0.distance(x[zone.left]);
    result.half_chord  = x_theta0[1];
    result.indentation = u0;
    result.conformity  = gaps.conformity;
    result.penetration = std::max(0., -min_gap_outside) / u0;
    result.nip_load    = -2. * body.load_resultant(1.)[0];
    return gaps;
  }

  std::string
  InverseContact::damp(const Zone &zone,
                       const Gaps &gaps,
                       Iterate    &iterate,
                       bool       &retry)
  {
    using namespace IterationControls;
    retry = false;
    // A residual that no longer moves will not move for a smaller update
    // either: refuse at once.
    const double before = iterate.accepted_residual;
    const bool   stalled =
      iterate.halvings > 0 &&
      std::abs(gaps.residual - before) < stalled_residual * before;
    if (iterate.halvings < max_halvings && !stalled)
      {
        ++iterate.halvings;
        pcout << "      (the conformity residual grew from " << std::scientific
              << std::setprecision(3) << before << " to " << gaps.residual
              << ": update halved)" << std::fixed << std::endl;
        body.set_solution(iterate.accepted_state);
        applied_pressure = iterate.accepted_pressure;
        iterate.f_from   = iterate.accepted_a;
        for (unsigned int k = 0; k < zone.m; ++k)
          iterate.a[k] =
            iterate.accepted_a[k] + IterationControls::halving_factor *
                                      (iterate.a[k] - iterate.accepted_a[k]);
        retry = true;
        return "";
      }
    std::ostringstream msg;
    const double       round_off =
      ToleranceFloor::conformity_round_off(parameters.geometry.outer_radius,
                                           gaps.u0);
    if (before < round_off)
      {
        msg << std::scientific << std::setprecision(3)
            << "the contact iteration stalled on round-off at theta0 = "
            << std::fixed << zone.theta0 * degrees_per_radian
            << " deg: conformity residual " << std::scientific << before
            << ", within the round-off of the gaps at u0 = " << std::fixed
            << gaps.u0 << " mm (" << std::scientific << round_off
            << "), above the tolerance " << conformity_tolerance
            << ": raise Contact/Conformity tolerance (and Control tolerance)";
        return msg.str();
      }
    msg << "the contact iteration diverges at theta0 = " << std::fixed
        << zone.theta0 * degrees_per_radian << " deg (conformity residual "
        << std::scientific << std::setprecision(3) << before
        << (stalled ? " stalls at " : " grows to ") << gaps.residual
        << " after " << iterate.halvings
        << " halving(s) of the update, u0 = " << std::fixed << gaps.u0
        << " mm): the nip is too large for this cover, or the mesh too "
           "coarse near it";
    return msg.str();
  }

  Eigen::MatrixXd
  InverseContact::sensitivities(const Zone &zone, const Gaps &gaps)
  {
    // The tangent is the one Newton factorised last in carry_pressure(),
    // one Newton update away from the converged state (two after a chord
    // step): close to the tangent there, which would cost another
    // assembly and factorisation and change no converged nip, only the
    // rate of the contact iteration a little.
    const auto                &cs    = *counter_surface;
    const double               u0    = gaps.u0;
    const std::vector<double> &knots = zone.knots;
    // One solve phase for all the hats' responses.
    std::vector<TrilinosWrappers::MPI::Vector> rhs, du(zone.m);
    for (unsigned int k = 0; k < zone.m; ++k)
      {
        rhs.push_back(body.pressure_load_derivative(
          [&knots, k](const double theta) { return hat(knots, k, theta); }));
        rhs.back() *= -1.;
        du[k].reinit(body.owned_solution()); // its layout, zero
      }
    body.solve_with_tangent(rhs, du);
    Eigen::MatrixXd J(zone.m, zone.m);
    for (unsigned int k = 0; k < zone.m; ++k)
      {
        const auto   dU   = nodal_values(du[k]);
        const double du0  = -dU[0][0];
        auto         dgap = [&](const unsigned int i) {
          return cs.gap_gradient(gaps.x[i], u0) * dU[i] +
                 cs.gap_derivative_u0(gaps.x[i], u0) * du0;
        };
        for (unsigned int j = 1; j < zone.m; ++j)
          J(j - 1, k) = dgap(j) / u0;
        J(zone.m - 1, k) =
          (zone.c_A * dgap(zone.above) - zone.c_B * dgap(zone.B)) / u0;
      }
    return J;
  }

  ContactResult
  InverseContact::solve(const double theta0)
  {
    const Zone zone = make_zone(theta0);
    body.set_step_log(false);
    ContactResult result;
    result.theta0 = theta0;
    Iterate iterate;
    initial_pressure(zone, iterate);
    iterate.accepted_residual = std::numeric_limits<double>::max();
    print_header(zone);
    for (unsigned int it = 1; it <= parameters.contact.max_iterations; ++it)
      {
        result.message = carry_pressure(zone, iterate, it);
        if (!result.message.empty())
          break;
        const std::vector<double> knots = zone.knots, a = iterate.a;
        applied_pressure = [knots, a](const double theta) {
          return interpolate(knots, a, theta);
        };
        applied_theta0 = theta0;
        iterate.f_from = a;
        result.values  = a;
        body.set_pressure([knots, a](const double theta, const double lambda) {
          return lambda * interpolate(knots, a, theta);
        });
        const Gaps gaps      = measure_gaps(zone, result);
        result.iterations    = it;
        result.min_pressure  = *std::min_element(a.begin(), a.end());
        result.peak_pressure = *std::max_element(a.begin(), a.end());
        pcout << std::setw(5) << it << std::scientific << std::setprecision(3)
              << std::setw(22) << gaps.conformity << std::fixed
              << std::setprecision(6) << std::setw(11) << gaps.u0
              << std::setw(13) << result.nip_load << std::setw(13)
              << result.min_pressure << std::endl;
        // Damping: an update that makes the conformity residual grow (or
        // the indentation negative), as full steps do on large nips, is
        // taken back and halved.
        if (it > 1 &&
            (!(gaps.u0 > 0) || gaps.residual > iterate.accepted_residual))
          {
            bool retry     = false;
            result.message = damp(zone, gaps, iterate, retry);
            if (retry)
              continue;
            break;
          }
        iterate.accepted_state    = body.owned_solution();
        iterate.accepted_pressure = applied_pressure;
        iterate.accepted_a        = iterate.a;
        iterate.accepted_residual = gaps.residual;
        iterate.halvings          = 0;
        if (!(gaps.u0 > 0))
          {
            result.message = "the indentation is not positive";
            break;
          }
        if (gaps.residual < conformity_tolerance)
          {
            result.converged = true;
            break;
          }
        if (far_from_goal(result, gaps.residual))
          {
            result.converged   = true;
            result.provisional = true;
            pcout << "      (provisional: theta0 is far from the target; "
                     "the control moves on)"
                  << std::endl;
            break;
          }
        const Eigen::MatrixXd J = sensitivities(zone, gaps);
        Eigen::VectorXd       rhs(zone.m);
        for (unsigned int j = 0; j < zone.m; ++j)
          rhs(j) = -gaps.g[j];
        const Eigen::VectorXd delta = J.colPivHouseholderQr().solve(rhs);
        for (unsigned int k = 0; k < zone.m; ++k)
          iterate.a[k] += delta(k);
      }
    result.knots = zone.knots;
    finish(zone, result);
    return result;
  }

  bool
  InverseContact::far_from_goal(const ContactResult &result,
                                const double         residual) const
  {
    using namespace IterationControls;
    if (!control_goal)
      return false;
    const ControlGoal &g    = *control_goal;
    const double       q    = g.by_load ? result.nip_load : result.indentation;
    const double       miss = std::abs(q / g.target - 1);
    // The checks of a converged nip must hold already: a negative pressure
    // or a penetration is for the control a failed theta0, not a miss.
    return std::isfinite(miss) && miss > provisional_miss * g.tolerance &&
           residual < provisional_fraction * miss && result.min_pressure >= 0 &&
           result.penetration <= parameters.contact.tolerance;
  }

  void
  InverseContact::print_header(const Zone &zone) const
  {
    // Its own precision: lines printed before may leave std::cout's low.
    std::ostringstream line;
    line << std::setprecision(6)
         << "Contact iteration, theta0 = " << zone.theta0 * degrees_per_radian
         << " deg, " << zone.m << " pressure parameters";
    pcout << line.str();
    if (body.has_nip_fitted_mesh())
      {
        const MeshQuality  q = body.cell_quality();
        std::ostringstream s;
        s << std::setprecision(3)
          << " (nip-fitted mesh: smallest corner Jacobian ratio "
          << q.min_jacobian_ratio << ", largest aspect ratio "
          << q.max_aspect_ratio << ")";
        pcout << s.str();
      }
    pcout << std::endl
          << " iter  conformity |gap|/u0   u0 [mm]      P [N/mm]   min f [MPa]"
          << std::endl;
  }

  void
  InverseContact::finish(const Zone &zone, ContactResult &result)
  {
    if (!result.converged && result.message.empty())
      {
        std::ostringstream s;
        s << std::setprecision(3)
          << "the contact iteration did not reach the conformity tolerance "
          << conformity_tolerance << " in " << parameters.contact.max_iterations
          << " iterations (reached " << result.conformity << ")";
        result.message = s.str();
      }
    if (result.converged && result.min_pressure < 0)
      {
        result.converged = false;
        result.message   = "the contact pressure is negative somewhere (min " +
                         std::to_string(result.min_pressure) +
                         " MPa): the surface would separate inside the zone" +
                         (zone.m < 4 ? " (only " + std::to_string(zone.m) +
                                         " surface node(s) lie in the zone: "
                                         "refine the mesh near the nip)"
                                     : std::string());
      }
    if (result.converged && result.penetration > parameters.contact.tolerance)
      {
        result.converged = false;
        result.message   = "the surface penetrates the indenter outside the "
                           "zone by " +
                         std::to_string(result.penetration) +
                         " u0: theta0 is too small for this load";
      }
    if (result.converged)
      {
        const NipSize size{zone.theta0, result.peak_pressure};
        if (std::abs(std::log(zone.theta0 / last_nip.theta0)) >
            IterationControls::min_growth_span)
          nip_before = last_nip;
        last_nip           = size;
        converged.state    = body.owned_solution();
        converged.pressure = applied_pressure;
        converged.theta0   = zone.theta0;
        return;
      }
    restore_converged(Converged(converged));
  }

  double
  InverseContact::pressure_growth() const
  {
    const double span = std::log(last_nip.theta0 / nip_before.theta0);
    if (!(nip_before.peak > 0 && last_nip.peak > 0 &&
          std::abs(span) > IterationControls::min_growth_span))
      return 1.;
    const double g = std::log(last_nip.peak / nip_before.peak) / span;
    return std::isfinite(g) ? std::clamp(g,
                                         IterationControls::min_pressure_growth,
                                         IterationControls::max_pressure_growth)
                            : 1.;
  }

  void
  InverseContact::restore_converged(const Converged &nip)
  {
    converged = nip;
    // The next nip starts from the last converged one (or from scratch if
    // there is none).
    TrilinosWrappers::MPI::Vector start(body.owned_solution());
    if (converged.pressure)
      start = converged.state;
    else
      start = 0;
    body.set_solution(start);
    applied_pressure = converged.pressure;
    applied_theta0   = converged.theta0;
  }

  bool
  InverseContact::start_from(const InverseContact &other)
  {
    // The roll problems behind both contact bodies (a scene's nip solver
    // iterates on its RollProblem).
    auto       *mine   = dynamic_cast<RollProblem *>(&body);
    const auto *theirs = dynamic_cast<const RollProblem *>(&other.body);
    if (!mine || !theirs || !other.converged.pressure)
      return false;
    // Its current state is that nip: a solve that fails goes back to it.
    if (!transfer_nested_displacement(theirs->body(), mine->body()))
      return false;
    Converged start;
    start.state    = body.owned_solution();
    start.pressure = other.converged.pressure;
    start.theta0   = other.converged.theta0;
    restore_converged(start);
    return true;
  }

  void
  write_contact_results(const ContactResult &result,
                        const std::string   &directory,
                        const std::string   &more)
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    constexpr double deg = degrees_per_radian;
    make_directories(directory);
    write_atomically(directory + "/contact.txt", [&](std::ostream &out) {
      out << std::setprecision(8)
          << "# rollnip contact (Batra's inverse iteration); mm, MPa, N/mm\n"
          << "status = " << (result.converged ? "converged" : "stopped")
          << '\n';
      if (!result.converged)
        out << "stopped_because = " << result.message << '\n';
      out << "half_nip_angle_theta0_deg = " << result.theta0 * deg << '\n'
          << "contact_iterations = " << result.iterations << '\n'
          << "indentation_u0_mm = " << result.indentation << '\n'
          << "nip_load_P_N_per_mm = " << result.nip_load << '\n'
          << "peak_pressure_MPa = " << result.peak_pressure << '\n'
          << "# the lowest pressure at a surface node inside the nip (it "
             "falls to 0 at the nip edge)\n"
          << "min_pressure_inside_nip_MPa = " << result.min_pressure << '\n'
          << "conformity_max_gap_over_u0 = " << result.conformity << '\n'
          << "penetration_outside_over_u0 = " << result.penetration << '\n';
      if (result.two_rolls)
        out << "# two covered rolls: indentation_u0_mm is the approach of "
               "the centres\n"
            << "roll_indentation_mm = " << result.roll_indentation << '\n'
            << "mating_roll_indentation_mm = " << result.mate_indentation
            << '\n'
            << "mating_roll_nip_load_P_N_per_mm = " << result.mate_nip_load
            << '\n'
            << "mating_roll_P_from_traction_N_per_mm = "
            << result.mate_load_from_traction << '\n'
            << "mating_roll_penetration_over_u0 = " << result.mate_penetration
            << '\n'
            << "two_roll_passes = " << result.outer_iterations << '\n';
      out << more;
    });
    write_atomically(directory + "/contact_pressure.csv",
                     [&](std::ostream &out) {
                       out << "theta_deg,pressure_MPa\n"
                           << std::setprecision(10);
                       for (unsigned int k = 0; k < result.knots.size(); ++k)
                         out
                           << result.knots[k] * deg << ','
                           << (k < result.values.size() ? result.values[k] : 0.)
                           << '\n';
                     });
  }
} // namespace rollnip
