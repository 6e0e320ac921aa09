#include <deal.II/base/timer.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/numerics/vector_tools.h>

#include <rollnip/three_d/core_tube.h>
#include <rollnip/three_d/slice_body.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>

namespace rollnip
{
  namespace three_d
  {
    namespace
    {
      /// The active nodes of all processes (each counts the x dofs it owns).
      unsigned int
      count_active(const std::set<types::global_dof_index> &active,
                   const IndexSet                          &owned,
                   const MPI_Comm                           communicator)
      {
        unsigned int n = 0;
        for (const auto x_dof : active)
          n += owned.is_element(x_dof);
        return Utilities::MPI::sum(n, communicator);
      }
    } // namespace

    void
    SliceBody::make_support_constraints(AffineConstraints<double> &c) const
    {
      const Functions::ZeroFunction<dim> zero(dim + 1);
      const auto                         mask = [](const int component) {
        std::vector<bool> m(dim + 1, false);
        if (component < 0)
          std::fill(m.begin(), m.begin() + dim, true);
        else
          m[component] = true;
        return ComponentMask(m);
      };
      using BC            = Parameters::BoundaryCondition;
      const auto &bc      = parameters.boundary_conditions.condition;
      const auto  support = [&](const types::boundary_id id, const int comp) {
        VectorTools::interpolate_boundary_values(
          dof_handler, id, zero, c, mask(comp));
      };
      // Fixed wins over symmetry where they meet: it goes in first. The
      // conditions were checked with the mesh (check_slice_scene()).
      support(SliceIds::inner_arc, -1);
      const double alpha = parameters.geometry.sector_angle;
      if (bc[SliceIds::far_edge] == BC::fixed)
        support(SliceIds::far_edge, -1);
      else if (bc[SliceIds::far_edge] == BC::symmetry)
        support(SliceIds::far_edge,
                std::abs(alpha - numbers::PI / 2) < 1e-12 ? 0 : 1);
      if (three_d.elastic_core) // simply supported at the journal
        {
          support(CoreIds::journal, 0);
          support(CoreIds::journal, 1);
        }
      support(SliceIds::symmetry_edge, 1);
      support(SliceIds::near_face, 2);
      if (three_d.fix_far_face)
        support(SliceIds::far_face, 2);
    }

    void
    SliceBody::make_constraints(const double u0)
    {
      for (const bool homogeneous : {false, true})
        {
          AffineConstraints<double> &c =
            homogeneous ? homogeneous_constraints : constraints;
          c.clear();
          c.reinit(relevant);
          make_support_constraints(c);
          if (!homogeneous)
            add_core_displacement(c);
          // The active node's update keeps it on the linearised indenter:
          // n . du = -g, solved for the dominant in-plane component.
          for (const types::global_dof_index x_dof : active)
            {
              const SurfaceNode   &node = surface.at(x_dof);
              const Tensor<1, dim> n    = gap_normal(node, u0);
              const unsigned int   k = std::abs(n[0]) >= std::abs(n[1]) ? 0 : 1;
              const types::global_dof_index dof = node.dofs[k];
              if (c.is_constrained(dof))
                continue;
              c.add_line(dof);
              for (unsigned int j = 0; j < 2; ++j)
                if (j != k)
                  c.add_entry(dof, node.dofs[j], -n[j] / n[k]);
              if (!homogeneous)
                c.set_inhomogeneity(dof, -gap(node, u0) / n[k]);
            }
          c.close();
        }
    }

    bool
    SliceBody::update_active_set(const double u0)
    {
      // Active stays active while its normal contact force exceeds c g
      // (its g is ~0: while pressed); a free node joins when it
      // penetrates. Every process decides its relevant nodes from the same
      // ghosted data, so the sets agree where they overlap.
      std::set<types::global_dof_index> next;
      for (const auto &[x_dof, node] : surface)
        {
          const double g      = gap(node, u0);
          double       lambda = 0;
          if (active.count(x_dof))
            {
              const Tensor<1, dim> n = gap_normal(node, u0);
              for (unsigned int c = 0; c < dim; ++c)
                lambda += n[c] * reactions[node.dofs[c]];
            }
          if (lambda - active_set_scale * node.weight * g > 0)
            next.insert(x_dof);
        }
      const bool changed = next != active;
      active             = std::move(next);
      return Utilities::MPI::logical_or(changed, communicator);
    }

    double
    SliceBody::active_gap(const double u0) const
    {
      double worst = 0;
      for (const auto x_dof : active)
        worst = std::max(worst, std::abs(gap(surface.at(x_dof), u0)));
      return Utilities::MPI::max(worst, communicator);
    }

    bool
    SliceBody::newton(const double u0, unsigned int &steps)
    {
      TrilinosWrappers::MPI::Vector du(owned, communicator),
        state(owned, communicator);
      // A steel core's stresses are differences of terms of order its G,
      // so its nodal forces carry a round-off that grows with its G over
      // the cover's (1.3e-10 of the reactions at 8e4, measured): there, a
      // residual that has stopped falling below 1e-13 times that ratio is
      // converged.
      const double floor =
        three_d.elastic_core
          ? 1e-13 * layer_laws.back()->shear_modulus() / law->shear_modulus()
          : 0.;
      // Output/Verbosity = detailed (or Nonlinear solver/Verbose): a line
      // per Newton step on rank 0, so that a run of an hour shows where it
      // is and how its solves go.
      const bool verbose = parameters.nonlinear_solver.verbose;
      const bool log =
        verbose && Utilities::MPI::this_mpi_process(communicator) == 0;
      Timer run_clock;
      if (log)
        std::cout << "    Newton at u0 = " << u0 << " mm\n"
                  << "      step  |R_u|/|F|   sum|J-1|/V  gap [mm]   "
                  << "active nodes  GMRES its   wall s" << std::endl;
      double previous = 1.;
      for (unsigned int it = 0; it < three_d.max_newton_iterations; ++it)
        {
          Timer step_clock;
          // The inhomogeneities are the current gaps: rebuilt every step.
          make_constraints(u0);
          assemble();
          if (update_active_set(u0))
            {
              make_constraints(u0);
              assemble();
            }
          else if (it > 0 &&
                   (residual_u < 1e-10 ||
                    (residual_u < floor && residual_u > 0.5 * previous)) &&
                   residual_q < 1e-12)
            {
              // The residuals are global, so every rank gets here together.
              const double gap = active_gap(u0); // collective
              if (gap < 1e-10 * parameters.geometry.outer_radius)
                {
                  if (log)
                    std::cout
                      << std::scientific << std::setprecision(3)
                      << "      converged: |R_u|/|F| = " << residual_u
                      << ", sum|J-1|/V = " << residual_q << ", gap = " << gap
                      << " mm" << std::fixed << std::setprecision(1) << ", "
                      << run_clock.wall_time() << " s" << std::defaultfloat
                      << std::setprecision(6) << std::endl;
                  return true;
                }
            }
          previous = residual_u;
          // The largest gap of an active node: u0 itself at the first
          // step (the indenter moved), then the linearisation's error.
          const double       gap_before = verbose ? active_gap(u0) : 0.;
          const unsigned int n_active =
            verbose ? count_active(active, owned, communicator) : 0;
          const unsigned int gmres_before =
            block_amg ? block_amg->n_iterations : 0;
          du = 0;
          solve_linear(du);
          constraints.distribute(du);
          state = solution;
          state += du;
          solution = state;
          ++steps;
          if (log)
            std::cout << "      " << std::setw(4) << it + 1 << std::scientific
                      << std::setprecision(3) << "  " << residual_u << "   "
                      << residual_q << "  " << gap_before << "  "
                      << std::setw(12) << n_active << "  " << std::setw(9)
                      << (block_amg ? std::to_string(block_amg->n_iterations -
                                                     gmres_before)
                                    : std::string("-"))
                      << std::fixed << std::setprecision(1) << "  "
                      << std::setw(7) << step_clock.wall_time()
                      << std::defaultfloat << std::setprecision(6) << std::endl;
        }
      if (log)
        std::cout << std::scientific << std::setprecision(3)
                  << "      not converged in " << three_d.max_newton_iterations
                  << " steps: |R_u|/|F| = " << residual_u << std::defaultfloat
                  << std::setprecision(6) << std::endl;
      return false;
    }

    SliceNip
    SliceBody::solve(const double u0)
    {
      // The core's deflection is ramped in with the first approach.
      const double       core_left = core_amplitude * (1. - core_factor);
      const unsigned int n_steps =
        std::max(1.,
                 std::ceil(std::max(std::abs(u0 - current_u0), core_left) /
                             three_d.approach_step -
                           1e-9));
      const double       start = current_u0, core_start = core_factor;
      unsigned int       steps        = 0;
      const unsigned int gmres_before = block_amg ? block_amg->n_iterations : 0;
      for (unsigned int s = 1; s <= n_steps; ++s)
        {
          const double u = start + (u0 - start) * s / n_steps;
          core_factor    = core_start + (1. - core_start) * s / n_steps;
          AssertThrow(newton(u, steps),
                      ExcMessage("Three d: Newton did not converge at u0 = " +
                                 std::to_string(u) +
                                 " mm (try a smaller Three d/Approach step)"));
          current_u0 = u;
        }
      SliceNip nip     = evaluate(u0);
      nip.newton_steps = steps;
      nip.linear_iterations =
        block_amg ? block_amg->n_iterations - gmres_before : 0;
      return nip;
    }

    SliceNip
    SliceBody::evaluate(const double u0) const
    {
      double force_x = 0, chord = 0, penetration = 0;
      double z_min = std::numeric_limits<double>::max(), z_max = -z_min;
      for (const auto &[x_dof, node] : surface)
        {
          const bool is_active = active.count(x_dof) > 0;
          if (is_active && owned.is_element(x_dof))
            force_x += reactions[x_dof];
          if (is_active)
            {
              const Point<dim> x = deformed(node);
              chord              = std::max(chord, x[1]);
              z_min              = std::min(z_min, x[2]);
              z_max              = std::max(z_max, x[2]);
            }
          else
            penetration = std::max(penetration, -gap(node, u0));
        }
      SliceNip nip;
      nip.u0 = u0;
      // The model is the half x2 >= 0 of the nip: the full nip carries
      // twice its resultant, per unit length of face.
      nip.P = -2. * Utilities::MPI::sum(force_x, communicator) /
              three_d.slice_thickness;
      nip.half_chord      = Utilities::MPI::max(chord, communicator);
      nip.max_penetration = Utilities::MPI::max(penetration, communicator);
      z_min               = Utilities::MPI::min(z_min, communicator);
      z_max               = Utilities::MPI::max(z_max, communicator);
      nip.contact_length  = z_max > z_min ? z_max - z_min : 0.;
      nip.active_nodes    = count_active(active, owned, communicator);
      return nip;
    }
  } // namespace three_d
} // namespace rollnip
