#include <deal.II/base/mpi.h>

#include <rollnip/contact/nip_estimates.h>
#include <rollnip/contact/two_roll_contact.h>
#include <rollnip/geometry/angles.h>
#include <rollnip/solvers/iteration_controls.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>
#include <variant>

namespace rollnip
{
  namespace
  {
    /// y(x) on the polygon through (x_i, y_i), x increasing; constant
    /// beyond its ends.
    double
    piecewise_linear(const std::vector<double> &x,
                     const std::vector<double> &y,
                     const double               at)
    {
      if (at <= x.front())
        return y.front();
      if (at >= x.back())
        return y.back();
      const std::size_t j =
        std::upper_bound(x.begin(), x.end(), at) - x.begin();
      const double w = (at - x[j - 1]) / (x[j] - x[j - 1]);
      return (1 - w) * y[j - 1] + w * y[j];
    }

    /// @p to - @p from, point by point.
    std::vector<Tensor<1, dim>>
    difference(const std::vector<Point<dim>> &to,
               const std::vector<Point<dim>> &from)
    {
      std::vector<Tensor<1, dim>> d(from.size());
      for (unsigned int j = 0; j < from.size(); ++j)
        d[j] = to[j] - from[j];
      return d;
    }

    /// Aitken's relaxation factor after @p omega from the last two changes
    /// of the surface (the first pass keeps @p omega).
    double
    aitken(const double                       omega,
           const std::vector<Tensor<1, dim>> &previous,
           const std::vector<Tensor<1, dim>> &change)
    {
      if (previous.empty())
        return omega;
      double num = 0, den = 0;
      for (unsigned int j = 0; j < change.size(); ++j)
        {
          const Tensor<1, dim> d = change[j] - previous[j];
          num += previous[j] * d;
          den += d * d;
        }
      return den > 0 ? std::clamp(-omega * num / den,
                                  IterationControls::relaxation_min,
                                  IterationControls::relaxation_max)
                     : omega;
    }

    /// Why the mating roll's mesh cannot take its contact edge at @p edge
    /// [rad] ("" if it can): past half of its Sector angle (@p sector) on
    /// the nip-fitted mesh, which is fitted no further (@p fitted), or at
    /// the end of the sector otherwise. Checked once the passes agree,
    /// before any refit.
    std::string
    beyond_mate_reach(const double edge, const bool fitted, const double sector)
    {
      const double reach = fitted ? 0.5 * sector : sector;
      if (edge < reach * (1 - 1e-9))
        return "";
      std::ostringstream s;
      s << std::setprecision(4) << "the mating roll's contact edge lies at "
        << edge * degrees_per_radian << " deg, "
        << (fitted ? "beyond half of" : "at the end of")
        << " Mating roll/Geometry/Sector angle (" << sector * degrees_per_radian
        << " deg)"
        << (fitted ? ", the largest nip its nip-fitted mesh takes" : "")
        << ": widen Mating roll/Geometry/Sector angle";
      return s.str();
    }
  } // namespace

  TwoRollContact::TwoRollContact(ContactBody                     &roll,
                                 const Parameters::AllParameters &parameters,
                                 const SceneDescription          &description,
                                 Parameters::AllParameters mate_parameters)
      : mate_parameters(std::move(mate_parameters))
      , roll(roll)
      , mate(this->mate_parameters, roll.communicator())
      , mate_surface(
          std::make_shared<DeformedRoll>(description.roll.outer_radius(),
                                         description.counter_radius()))
      , contact(roll, parameters, description, mate_surface)
      , pcout(std::cout,
              Utilities::MPI::this_mpi_process(roll.communicator()) == 0)
  {
    mate.setup();
    mate.set_step_log(false);
  }

  std::vector<Point<dim>>
  TwoRollContact::deformed(const std::vector<SurfaceNode>    &nodes,
                           const std::vector<Tensor<1, dim>> &u)
  {
    std::vector<Point<dim>> x;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      x.push_back(u.empty() ? nodes[i].X : nodes[i].X + u[i]);
    return x;
  }

  std::vector<Point<dim>>
  TwoRollContact::mate_shape() const
  {
    auto u =
      surface_values(mate_nodes, mate.current_solution(), mate.locally_owned());
    // As for the first roll (InverseContact): linear theory moves the
    // surface along its reference normal only.
    if (scene().analysis.theory == Parameters::Theory::linear)
      for (unsigned int i = 0; i < u.size(); ++i)
        {
          const Tensor<1, dim> n = mate_nodes[i].X / mate_nodes[i].X.norm();
          u[i]                   = (u[i] * n) * n;
        }
    return deformed(mate_nodes, u);
  }

  std::string
  TwoRollContact::load_mate(const ContactResult &result)
  {
    // The roll's pressure as a function of x2 along the common tangent
    // (increasing near the nip, where the pressure is): of the deformed
    // surfaces, where the two coincide; in linear theory, which loads the
    // reference surfaces, of those, so that both carry the same P.
    const bool  linear = scene().analysis.theory == Parameters::Theory::linear;
    const auto &nodes  = contact.surface_nodes();
    const auto  x      = linear ? deformed(nodes, {})
                                : deformed(nodes, contact.surface_displacements());
    std::vector<double> x2, theta;
    for (unsigned int i = 0; i < x.size(); ++i)
      if (x2.empty() || x[i][1] > x2.back())
        {
          x2.push_back(x[i][1]);
          theta.push_back(nodes[i].theta);
        }
    // The mating nodes' x2 as a function of their reference angle.
    const auto          y = linear ? deformed(mate_nodes, {}) : mate_shape();
    std::vector<double> mate_theta, mate_x2;
    for (unsigned int j = 0; j < y.size(); ++j)
      {
        mate_theta.push_back(mate_nodes[j].theta);
        mate_x2.push_back(std::abs(y[j][1]));
      }
    const std::function<double(double)> f = contact.pressure();
    const double                        edge =
      linear ? scene().roll.outer_radius() * std::sin(result.theta0)
                                    : result.half_chord;
    // The mating point at the edge, on the part of its surface where x2
    // still grows with the angle.
    std::size_t n = 1;
    while (n < mate_x2.size() && mate_x2[n] > mate_x2[n - 1])
      ++n;
    mate_edge_angle =
      piecewise_linear({mate_x2.begin(), mate_x2.begin() + n},
                       {mate_theta.begin(), mate_theta.begin() + n},
                       edge);
    const std::function<double(double)> to = [=](const double theta_mate) {
      const double at = piecewise_linear(mate_theta, mate_x2, theta_mate);
      return at >= edge ? 0. : f(piecewise_linear(x2, theta, at));
    };
    const std::function<double(double)> from = mate_pressure;
    mate.set_pressure([from, to](const double theta, const double lambda) {
      const double f0 = from ? from(theta) : 0.;
      return f0 + lambda * (to(theta) - f0);
    });
    RunStatus status = mate_pressure ? mate.run(true, 1.) : mate.run(false);
    if (!status.converged)
      return "the mating roll cannot carry the contact pressure (" +
             status.message + ")";
    mate_pressure = to;
    mate.set_pressure([to](const double theta, const double lambda) {
      return lambda * to(theta);
    });
    return "";
  }

  void
  TwoRollContact::measure_mate(ContactResult &result) const
  {
    const auto y            = mate_shape();
    result.two_rolls        = true;
    result.roll_indentation = result.indentation;
    result.mate_indentation = mate_description().outer_radius() - y[0][0];
    result.indentation      = result.roll_indentation + result.mate_indentation;
    result.mate_nip_load    = -2. * mate.load_resultant(1.)[0];
    // The first roll's deformed surface seen from the mating roll: its
    // nodes outside the zone must not lie inside it.
    DeformedRoll roll_surface(mate_description().outer_radius(),
                              scene().roll.outer_radius());
    roll_surface.set_shape(
      deformed(contact.surface_nodes(), contact.surface_displacements()));
    double min_gap = 0;
    for (const auto &p : y)
      if (std::abs(p[1]) > result.half_chord)
        min_gap =
          std::min(min_gap, roll_surface.gap(p, result.mate_indentation));
    result.mate_penetration = std::max(0., -min_gap) / result.indentation;
  }

  void
  TwoRollContact::fit_mate_mesh(const double angle)
  {
    mate_fit_angle = std::min(angle, mate.max_nip_angle());
    mate.fit_mesh_to_nip(mate_fit_angle);
    mate_nodes = outer_surface_nodes(mate.dofs());
  }

  bool
  TwoRollContact::refit_mate_mesh()
  {
    // The nip at a given theta0 depends on where the mating roll's mesh is
    // fitted: to the control tolerance, so that a load-controlled nip is
    // the nip of its theta0 to that tolerance.
    const double tolerance =
      std::min(IterationControls::mate_refit_tolerance,
               mate_parameters.contact.control_tolerance);
    // Every process refits, or none (the refit is collective): rank 0's
    // edge, so that round-off does not split them at a tight tolerance.
    mate_edge_angle =
      Utilities::MPI::broadcast(communicator(), mate_edge_angle, 0);
    if (!mate.has_nip_fitted_mesh() ||
        mate_refits >= IterationControls::max_mate_refits ||
        std::abs(mate_edge_angle - mate_fit_angle) <=
          tolerance * mate_fit_angle)
      return false;
    ++mate_refits;
    pcout << "  the mating roll's contact edge lies at "
          << mate_edge_angle * degrees_per_radian << " deg, its mesh at "
          << mate_fit_angle * degrees_per_radian << " deg: refitted"
          << std::endl;
    fit_mate_mesh(mate_edge_angle);
    return true;
  }

  void
  TwoRollContact::restore(const InverseContact::Converged &roll_nip)
  {
    contact.restore_converged(roll_nip);
    if (mate.has_nip_fitted_mesh() && mate_converged_fit_angle > 0)
      fit_mate_mesh(mate_converged_fit_angle);
    if (mate_converged_pressure)
      mate.set_solution(mate_converged);
    else
      {
        TrilinosWrappers::MPI::Vector zero(mate.body().owned_solution());
        zero = 0;
        mate.set_solution(zero);
      }
    mate_pressure = mate_converged_pressure;
    const auto f  = mate_pressure;
    mate.set_pressure([f](const double theta, const double lambda) {
      return f ? lambda * f(theta) : 0.;
    });
  }

  ContactResult
  TwoRollContact::solve(const double theta0)
  {
    const double estimate = fit_mate_to_estimate(theta0);
    // The passes converge the roll's contact many times: a failed nip goes
    // back to this one.
    const InverseContact::Converged last = contact.last_converged();
    // Two half-spaces: the exact relaxation is G_mate / (G + G_mate).
    const double G     = scene().roll.surface_layer().shear_modulus();
    const double G_m   = mate_description().surface_layer().shear_modulus();
    double       omega = G_m / (G + G_m);
    const double tolerance =
      IterationControls::two_roll_tolerance_factor * contact.tolerance();

    std::vector<Point<dim>>     shape = mate_shape();
    std::vector<Tensor<1, dim>> previous_change;
    ContactResult               result;
    pcout << "Two-roll contact, theta0 = " << theta0 * degrees_per_radian
          << " deg" << std::endl;
    const unsigned int max_passes =
      std::get<CounterKind::CoveredRoll>(scene().counter).max_iterations;
    for (unsigned int k = 1; k <= max_passes; ++k)
      {
        mate_surface->set_shape(shape);
        result                  = contact.solve(theta0);
        result.outer_iterations = k;
        if (result.converged)
          result.message = load_mate(result);
        if (!result.message.empty())
          {
            result.converged = false;
            result.message =
              "two rolls, pass " + std::to_string(k) + ": " + result.message;
            break;
          }
        // How far the mating surface moved under the new pressure.
        const std::vector<Tensor<1, dim>> change =
          difference(mate_shape(), shape);
        double moved = 0;
        for (const auto &d : change)
          moved = std::max(moved, d.norm() / result.indentation);
        measure_mate(result);
        pcout << "  pass " << k << ": mating surface moved " << std::scientific
              << std::setprecision(3) << moved << " u0, relaxation "
              << std::fixed << omega << ", approach " << std::setprecision(6)
              << result.indentation << " mm, P " << result.nip_load
              << " N/mm (mating roll " << result.mate_nip_load << ")\n";
        result.converged = false;
        const std::string beyond =
          moved < tolerance
            ? beyond_mate_reach(mate_edge_angle,
                                mate.has_nip_fitted_mesh(),
                                mate_parameters.geometry.sector_angle)
            : "";
        if (!beyond.empty())
          {
            result.message =
              "two rolls, pass " + std::to_string(k) + ": " + beyond;
            break;
          }
        if (moved < tolerance && refit_mate_mesh())
          {
            result.message = "the two rolls did not agree after the mating "
                             "roll's mesh was refitted in pass " +
                             std::to_string(k);
            shape = mate_shape();
            previous_change.clear();
            continue;
          }
        if (moved < tolerance)
          {
            result.converged = true;
            break;
          }
        omega = aitken(omega, previous_change, change);
        for (unsigned int j = 0; j < shape.size(); ++j)
          shape[j] += omega * change[j];
        previous_change = change;
        result.message  = "the two rolls did not agree on the mating "
                          "surface in " +
                         std::to_string(k) + " passes (it still moves " +
                         std::to_string(moved) + " u0)";
      }
    if (result.converged)
      {
        // Equilibrium of the mating roll from its own stresses.
        result.mate_load_from_traction =
          load_from_traction(mate.surface_data(1.).outer);
        keep_converged(result, estimate);
      }
    else
      restore(last);
    return result;
  }

  double
  TwoRollContact::fit_mate_to_estimate(const double theta0)
  {
    // The estimate, scaled as it was off at the last converged nip; the
    // passes refit the mesh once they show the edge.
    const double estimate =
      NipEstimates::mate_nip_angle(scene().roll.outer_radius(),
                                   scene().counter_radius(),
                                   theta0);
    mate_refits = 0;
    if (mate.has_nip_fitted_mesh())
      fit_mate_mesh(mate_angle_factor * estimate);
    else
      mate_nodes = outer_surface_nodes(mate.dofs());
    return estimate;
  }

  void
  TwoRollContact::keep_converged(ContactResult &result, const double estimate)
  {
    result.message           = "";
    mate_converged           = mate.body().owned_solution();
    mate_converged_pressure  = mate_pressure;
    mate_converged_fit_angle = mate_fit_angle;
    if (mate.has_nip_fitted_mesh())
      mate_angle_factor = mate_fit_angle / estimate;
  }

  void
  TwoRollContact::write_results(const ContactResult &result,
                                const std::string   &directory,
                                const unsigned int   step,
                                const bool           with_vtu)
  {
    mate.set_output_directory(directory + "/mating_roll");
    // In the first roll's frame: its centre at the distance D of the
    // centres, half a turn about D/2 on the line of centres.
    const double D = scene().roll.outer_radius() +
                     mate_description().outer_radius() - result.indentation;
    mate.set_vtu_placement(Point<dim>(D / 2, 0.));
    if (with_vtu)
      mate.write_vtu(step, 1.);
    RunStatus status;
    status.converged     = result.converged;
    status.load_fraction = 1.;
    status.message       = "contact: " + result.message;
    mate.write_results(status);
  }
} // namespace rollnip
