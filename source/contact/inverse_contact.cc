#include <deal.II/base/mpi.h>

#include <rollnip/boundary_ids.h>
#include <rollnip/contact/inverse_contact.h>
#include <rollnip/output/atomic_file.h>

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

  InverseContact::InverseContact(RollProblem                     &problem,
                                 const Parameters::AllParameters &parameters)
      : problem(problem)
      , parameters(parameters)
      , indenter(parameters.geometry.outer_radius,
                 parameters.contact.indenter_radius)
      , pcout(std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      , conformity_tolerance(
          parameters.contact.mode == Parameters::ContactMode::nip_angle
            ? parameters.contact.tolerance
            : std::min(parameters.contact.tolerance,
                       0.1 * parameters.contact.control_tolerance))
  {}

  void
  InverseContact::collect_surface_nodes()
  {
    std::vector<double> flat;
    for (const auto &cell : problem.dofs().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == BoundaryIds::outer_arc)
            for (unsigned int v = 0; v < 2; ++v)
              {
                const Point<dim> X = cell->face(f)->vertex(v);
                // Sectors reach 180 deg, where atan2 may return -pi for a
                // round-off negative X[1]: angles are taken in [0, 2 pi).
                double theta = std::atan2(X[1], X[0]);
                if (theta < -0.5 * numbers::PI)
                  theta += 2 * numbers::PI;
                flat.insert(flat.end(),
                            {theta,
                             X[0],
                             X[1],
                             double(cell->face(f)->vertex_dof_index(v, 0)),
                             double(cell->face(f)->vertex_dof_index(v, 1))});
              }
    std::map<long long, SurfaceNode> unique;
    for (const auto &part : Utilities::MPI::all_gather(MPI_COMM_WORLD, flat))
      for (std::size_t i = 0; i < part.size(); i += 5)
        unique[std::llround(part[i] * 1e9)] =
          SurfaceNode{part[i],
                      Point<dim>(part[i + 1], part[i + 2]),
                      {types::global_dof_index(part[i + 3]),
                       types::global_dof_index(part[i + 4])}};
    nodes.clear();
    for (const auto &entry : unique)
      nodes.push_back(entry.second);
  }

  std::vector<Tensor<1, dim>>
  InverseContact::nodal_values(const TrilinosWrappers::MPI::Vector &v) const
  {
    std::vector<double> values(dim * nodes.size(), 0.);
    const IndexSet     &owned = problem.locally_owned();
    for (unsigned int i = 0; i < nodes.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        if (owned.is_element(nodes[i].dof[d]))
          values[dim * i + d] = v[nodes[i].dof[d]];
    Utilities::MPI::sum(values, MPI_COMM_WORLD, values);
    std::vector<Tensor<1, dim>> u(nodes.size());
    for (unsigned int i = 0; i < nodes.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        u[i][d] = values[dim * i + d];
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
    if (problem.has_nip_fitted_mesh())
      return problem.max_nip_angle();
    if (nodes.empty())
      collect_surface_nodes();
    // The edge row needs two free nodes beyond the zone.
    return nodes.size() > 3 ? nodes[nodes.size() - 3].theta : 0.;
  }

  ContactResult
  InverseContact::solve(const double theta0)
  {
    // On the nip-fitted mesh the contact edge is moved onto a node.
    if (problem.has_nip_fitted_mesh())
      {
        problem.fit_mesh_to_nip(theta0);
        nodes.clear();
      }
    if (nodes.empty())
      collect_surface_nodes();
    problem.set_step_log(false);
    ContactResult result;
    result.theta0 = theta0;
    AssertThrow(nodes.size() > 2 && std::abs(nodes[0].theta) < 1e-12,
                ExcMessage("the outer surface has no node on the line of "
                           "centres (R0, 0)"));

    // Knots: the nodes below theta0, then theta0 itself (f = 0 there).
    // Every knot but the first carries a zero-gap equation, and so does
    // theta0, so that every node of the zone is held on the indenter.
    // A node within round-off of theta0 is the edge (always so on the
    // nip-fitted mesh).
    unsigned int m = 0;
    while (m < nodes.size() && nodes[m].theta < theta0 * (1 - 1e-12))
      ++m;
    AssertThrow(m < nodes.size(),
                ExcMessage("Contact: the contact zone reaches the end of the "
                           "outer arc"));
    const unsigned int above = m; // first node beyond theta0
    AssertThrow(m >= 2,
                ExcMessage("Contact/Half nip angle is too small for the mesh: "
                           "refine near theta = 0 (at least two surface nodes "
                           "must lie in the contact zone)"));
    std::vector<double> knots;
    for (unsigned int k = 0; k < m; ++k)
      knots.push_back(nodes[k].theta);
    knots.push_back(theta0);

    // Where theta0 falls between two nodes, for its interpolated position.
    const unsigned int left   = above - 1;
    const double       weight = std::min(1.,
                                   (theta0 - nodes[left].theta) /
                                     (nodes[above].theta - nodes[left].theta));

    // Initial guess: a Hertz-like parabola with the peak pressure of a
    // rigid cylinder on an incompressible half-space, E* = 4 G.
    const double R0 = parameters.geometry.outer_radius;
    const double G  = 2 * (parameters.material.C1 + parameters.material.C2);
    const double R_eff =
      indenter.is_flat() ? R0 : 1. / (1. / R0 + 1. / indenter.radius());
    const double half_width = R0 * std::sin(theta0);
    const double p_hertz    = 4 * G * half_width / (2 * R_eff);
    // Warm start from the pressure of the current state, stretched to the
    // new zone and scaled as in Hertz (peak pressure ~ nip width).
    std::vector<double> a(m), f_from(m, 0.);
    for (unsigned int k = 0; k < m; ++k)
      {
        if (applied_pressure)
          {
            f_from[k] = applied_pressure(knots[k]);
            a[k]      = applied_pressure(knots[k] * applied_theta0 / theta0) *
                   theta0 / applied_theta0;
          }
        else
          a[k] = p_hertz *
                 std::sqrt(std::max(0., 1 - std::pow(knots[k] / theta0, 2)));
      }

    TrilinosWrappers::MPI::Vector saved(
      problem.current_solution().locally_owned_elements(), MPI_COMM_WORLD);
    TrilinosWrappers::MPI::Vector du(saved);
    // The last accepted contact iterate, for the damping of the update.
    TrilinosWrappers::MPI::Vector accepted_state(saved);
    std::function<double(double)> accepted_pressure;
    std::vector<double>           accepted_a;
    double       accepted_residual = std::numeric_limits<double>::max();
    unsigned int halvings          = 0;

    pcout << "Contact iteration, theta0 = " << theta0 * 180 / numbers::PI
          << " deg, " << m << " pressure parameters";
    if (problem.has_nip_fitted_mesh())
      {
        const MeshQuality  q = problem.cell_quality();
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
    for (unsigned int it = 1; it <= parameters.contact.max_iterations; ++it)
      {
        // Solve the cover for the pressure a, ramping from the last one;
        // halve the update if that fails.
        bool        solved = false;
        std::string why;
        for (unsigned int attempt = 0; attempt < 4 && !solved; ++attempt)
          {
            saved = problem.current_solution();
            const std::function<double(double)> from = applied_pressure;
            const std::vector<double>           to   = a;
            problem.set_pressure(
              [knots, from, to](const double theta, const double lambda) {
                const double f0 = from ? from(theta) : 0.;
                return f0 + lambda * (interpolate(knots, to, theta) - f0);
              });
            // From a converged contact state the change is small: try the
            // whole update in one step (cut back if needed).
            const RunStatus status =
              applied_pressure ? problem.run(true, 1.) : problem.run(false);
            solved = status.converged;
            if (!solved)
              why = status.message;
            if (!solved)
              {
                problem.set_solution(saved);
                if (!applied_pressure)
                  break; // nothing smaller to retry from
                // The run carried the fraction status.load_fraction of
                // the update: retry just below it (at most half).
                const double factor =
                  status.load_fraction > 0
                    ? std::min(0.5, std::max(0.1, 0.8 * status.load_fraction))
                    : 0.5;
                for (unsigned int k = 0; k < m; ++k)
                  a[k] = f_from[k] + factor * (a[k] - f_from[k]);
              }
          }
        if (!solved)
          {
            result.message =
              applied_pressure
                ? "the cover cannot carry the pressure update of contact "
                  "iteration " +
                    std::to_string(it) + ", even reduced 3 times (" + why + ")"
                : "the cover cannot carry the first pressure guess (" + why +
                    ")";
            break;
          }
        applied_pressure = [knots, a](const double theta) {
          return interpolate(knots, a, theta);
        };
        applied_theta0 = theta0;
        for (unsigned int k = 0; k < m; ++k)
          f_from[k] = a[k];
        result.values = a;
        problem.set_pressure(
          [knots, a](const double theta, const double lambda) {
            return lambda * interpolate(knots, a, theta);
          });

        // Gaps at the equation points.
        const auto   U        = nodal_values(problem.current_solution());
        const double u0       = -U[0][0];
        auto         position = [&](const unsigned int i) {
          return Point<dim>(nodes[i].X + U[i]);
        };
        const Point<dim> x_theta0 =
          Point<dim>((1 - weight) * position(left) + weight * position(above));
        // Equations, scaled by u0 (eq. 7.2): zero gap at the nodes
        // 1..m-1 of the zone, and the edge row: beyond a smooth contact
        // edge the gap grows like (theta - theta0)^(3/2), so the gaps of
        // the first two free nodes A = above, B = above + 1 satisfy
        //   g_A (theta_B - theta0)^(3/2) - g_B (theta_A - theta0)^(3/2) = 0.
        // At theta0 = theta_A it reads g_A = 0. When theta0 passes a node,
        // the node joins the zone with its own pressure value, so P jumps
        // by an amount of the order of the discretisation error (2 % on
        // the coarsest default mesh, 0.2 % on level 3; doc/intro.md
        // section 7). (Holding the edge point x(theta0) on the indenter
        // instead pulled the whole edge cell on: ~10 % jumps.)
        AssertThrow(above + 1 < nodes.size(),
                    ExcMessage("Contact: the contact zone reaches the end of "
                               "the outer arc"));
        const unsigned int B    = above + 1;
        const double       span = nodes[B].theta - nodes[above].theta;
        const double       c_A =
          std::pow(std::max(0., nodes[B].theta - theta0) / span, 1.5);
        const double c_B =
          std::pow(std::max(0., nodes[above].theta - theta0) / span, 1.5);
        const unsigned int  n_eq = m;
        std::vector<double> g(n_eq);
        for (unsigned int j = 1; j < m; ++j)
          g[j - 1] = indenter.gap(position(j), u0) / u0;
        g[n_eq - 1] = (c_A * indenter.gap(position(above), u0) -
                       c_B * indenter.gap(position(B), u0)) /
                      u0;

        double conformity = 0, residual = std::abs(g[n_eq - 1]);
        for (unsigned int j = 0; j + 1 < n_eq; ++j)
          {
            conformity = std::max(conformity, std::abs(g[j]));
            residual   = std::max(residual, std::abs(g[j]));
          }
        double min_gap_outside = std::numeric_limits<double>::max();
        for (unsigned int i = above; i < nodes.size(); ++i)
          min_gap_outside =
            std::min(min_gap_outside, indenter.gap(position(i), u0));

        // The deformed contact arc from the line of centres to theta0.
        result.half_arc = 0;
        for (unsigned int i = 1; i <= left; ++i)
          result.half_arc += position(i).distance(position(i - 1));
        result.half_arc += x_theta0.distance(position(left));
        result.half_chord    = x_theta0[1];
        result.iterations    = it;
        result.indentation   = u0;
        result.conformity    = conformity;
        result.penetration   = std::max(0., -min_gap_outside) / u0;
        result.nip_load      = -2. * problem.load_resultant(1.)[0];
        result.min_pressure  = *std::min_element(a.begin(), a.end());
        result.peak_pressure = *std::max_element(a.begin(), a.end());
        pcout << std::setw(5) << it << std::scientific << std::setprecision(3)
              << std::setw(22) << conformity << std::fixed
              << std::setprecision(6) << std::setw(11) << u0 << std::setw(13)
              << result.nip_load << std::setw(13) << result.min_pressure
              << std::endl;
        // Damping: a Newton update that makes the conformity residual grow
        // (or the indentation negative), as full steps do on large nips,
        // is taken back and halved, up to 4 times in a row.
        if (it > 1 && (!(u0 > 0) || residual > accepted_residual))
          {
            // A residual that no longer moves will not move for a smaller
            // update either: refuse at once.
            const bool stalled =
              halvings > 0 &&
              std::abs(residual - accepted_residual) < 1e-3 * accepted_residual;
            if (halvings < 4 && !stalled)
              {
                ++halvings;
                pcout << "      (the conformity residual grew from "
                      << std::scientific << std::setprecision(3)
                      << accepted_residual << " to " << residual
                      << ": update halved)" << std::fixed << std::endl;
                problem.set_solution(accepted_state);
                applied_pressure = accepted_pressure;
                f_from           = accepted_a;
                for (unsigned int k = 0; k < m; ++k)
                  a[k] = accepted_a[k] + 0.5 * (a[k] - accepted_a[k]);
                continue;
              }
            std::ostringstream msg;
            msg << std::scientific << std::setprecision(3)
                << "the contact iteration diverges at theta0 = " << std::fixed
                << theta0 * 180 / numbers::PI << " deg (conformity residual "
                << std::scientific << accepted_residual
                << (stalled ? " stalls at " : " grows to ") << residual
                << " after " << halvings
                << " halving(s) of the update, u0 = " << std::fixed << u0
                << " mm): the nip is too large for this cover, or the mesh "
                   "too coarse near it";
            result.message = msg.str();
            break;
          }
        accepted_state    = problem.current_solution();
        accepted_pressure = applied_pressure;
        accepted_a        = a;
        accepted_residual = residual;
        halvings          = 0;
        if (!(u0 > 0))
          {
            result.message = "the indentation is not positive";
            break;
          }
        if (residual < conformity_tolerance)
          {
            result.converged = true;
            break;
          }

        // Sensitivities: one factorisation, one solve per parameter.
        problem.assemble(1., true);
        problem.factorize_tangent();
        Eigen::MatrixXd J(n_eq, m);
        for (unsigned int k = 0; k < m; ++k)
          {
            TrilinosWrappers::MPI::Vector rhs =
              problem.pressure_load_derivative([&knots, k](const double theta) {
                return hat(knots, k, theta);
              });
            rhs *= -1.;
            du = 0;
            problem.solve_with_tangent(rhs, du);
            const auto   dU  = nodal_values(du);
            const double du0 = -dU[0][0];
            auto dgap = [&](const Point<dim> &x, const Tensor<1, dim> &dx) {
              return indenter.gap_gradient(x, u0) * dx +
                     indenter.gap_derivative_u0(x, u0) * du0;
            };
            for (unsigned int j = 1; j < m; ++j)
              J(j - 1, k) = dgap(position(j), dU[j]) / u0;
            J(n_eq - 1, k) = (c_A * dgap(position(above), dU[above]) -
                              c_B * dgap(position(B), dU[B])) /
                             u0;
          }
        Eigen::VectorXd rhs(n_eq);
        for (unsigned int j = 0; j < n_eq; ++j)
          rhs(j) = -g[j];
        const Eigen::VectorXd delta = J.colPivHouseholderQr().solve(rhs);
        for (unsigned int k = 0; k < m; ++k)
          a[k] += delta(k);
      }

    result.knots = knots;
    if (!result.converged && result.message.empty())
      result.message = "the contact iteration did not reach the conformity "
                       "tolerance " +
                       std::to_string(conformity_tolerance) + " in " +
                       std::to_string(parameters.contact.max_iterations) +
                       " iterations (reached " +
                       std::to_string(result.conformity) + ")";
    if (result.converged && result.min_pressure < 0)
      {
        result.converged = false;
        result.message   = "the contact pressure is negative somewhere (min " +
                         std::to_string(result.min_pressure) +
                         " MPa): the surface would separate inside the zone" +
                         (m < 4 ? " (only " + std::to_string(m) +
                                    " surface node(s) lie in the zone: refine "
                                    "the mesh near the nip)"
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
        converged_state    = problem.current_solution();
        converged_pressure = applied_pressure;
        converged_theta0   = theta0;
      }
    else
      {
        // Undo the failed nip: the next one starts from the last solution
        // (or from scratch if there is none).
        if (converged_pressure)
          problem.set_solution(converged_state);
        else
          {
            TrilinosWrappers::MPI::Vector zero(saved);
            zero = 0;
            problem.set_solution(zero);
          }
        applied_pressure = converged_pressure;
        applied_theta0   = converged_theta0;
      }
    return result;
  }

  void
  write_contact_results(const ContactResult &result,
                        const std::string   &directory)
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    constexpr double deg = 180. / numbers::PI;
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
          << "min_pressure_MPa = " << result.min_pressure << '\n'
          << "conformity_max_gap_over_u0 = " << result.conformity << '\n'
          << "penetration_outside_over_u0 = " << result.penetration << '\n';
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
