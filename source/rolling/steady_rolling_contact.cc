#include <deal.II/lac/sparse_direct.h>

#include <rollnip/rolling/steady_rolling.h>

#include <cmath>
#include <limits>

namespace rollnip
{
  Point<dim>
  SteadyRolling::indenter_centre() const
  {
    return Point<dim>(layout.radii().back() + scene.indenter_radius - u0, 0.);
  }

  Point<dim>
  SteadyRolling::deformed(const SurfaceNode &node) const
  {
    return node.X +
           Tensor<1, dim>({solution(node.dofs[0]), solution(node.dofs[1])});
  }

  /// The gap to the mating roll's circle (a flat one: the plane x = R0 -
  /// u0); negative: penetration.
  double
  SteadyRolling::gap(const SurfaceNode &node) const
  {
    const Point<dim> x = deformed(node);
    if (std::isinf(scene.indenter_radius))
      return layout.radii().back() - u0 - x[0];
    return x.distance(indenter_centre()) - scene.indenter_radius;
  }

  /// The unit normal of the counter surface at the node's projection,
  /// pointing into the cover: the direction of the contact force on it.
  Tensor<1, dim>
  SteadyRolling::gap_normal(const SurfaceNode &node) const
  {
    if (std::isinf(scene.indenter_radius))
      return Tensor<1, dim>({-1., 0.});
    const Tensor<1, dim> d = deformed(node) - indenter_centre();
    return d / d.norm();
  }

  /// The bond fixed, and every active node's update keeping it on the
  /// linearised counter surface, n . du = -g, solved for its dominant
  /// component.
  void
  SteadyRolling::make_constraints()
  {
    constraints.clear();
    for (const auto dof : bond_dofs)
      constraints.add_line(dof);
    for (const auto x_dof : active)
      {
        const SurfaceNode   &node = surface.at(x_dof);
        const Tensor<1, dim> n    = gap_normal(node);
        const unsigned int   k    = std::abs(n[0]) >= std::abs(n[1]) ? 0 : 1;
        const auto           dof  = node.dofs[k];
        constraints.add_line(dof);
        constraints.add_entry(dof, node.dofs[1 - k], -n[1 - k] / n[k]);
        constraints.set_inhomogeneity(dof, -gap(node) / n[k]);
      }
    constraints.close();
  }

  /// An active node stays while it is pressed (n . reaction > 0), a free
  /// one joins when it penetrates.
  bool
  SteadyRolling::update_active_set()
  {
    const double scale =
      laws.back()->shear_modulus(); // force per mm of gap [N/mm^2]
    std::set<types::global_dof_index> next;
    for (const auto &[x_dof, node] : surface)
      {
        double lambda = 0;
        if (active.count(x_dof))
          {
            const Tensor<1, dim> n = gap_normal(node);
            lambda =
              n[0] * reactions(node.dofs[0]) + n[1] * reactions(node.dofs[1]);
          }
        if (lambda - scale * gap(node) > 0)
          next.insert(x_dof);
      }
    const bool changed = next != active;
    active             = std::move(next);
    return changed;
  }

  /// One Newton step with the active set updated first; returns the
  /// largest entry of the update, @p changed whether the set changed.
  double
  SteadyRolling::newton_step(bool &changed)
  {
    make_constraints();
    assemble();
    changed = update_active_set();
    if (changed)
      {
        make_constraints();
        assemble();
      }
    dealii::Vector<double> du(solution.size());
    SparseDirectUMFPACK    direct;
    direct.initialize(matrix);
    direct.vmult(du, rhs);
    constraints.distribute(du);
    solution += du;
    ++newton_count;
    const double size = du.linfty_norm();
    return std::isfinite(size) ? size : std::numeric_limits<double>::max();
  }

  /// Newton steps until the set stays and the update is below 1e-10 R0;
  /// then the reactions of the converged state.
  bool
  SteadyRolling::newton(const unsigned int max_iterations)
  {
    const double R0 = layout.radii().back();
    for (unsigned int it = 0; it < max_iterations; ++it)
      {
        bool         changed = false;
        const double size    = newton_step(changed);
        if (size == std::numeric_limits<double>::max())
          return false;
        if (!changed && size < 1e-10 * R0)
          {
            assemble();
            return true;
          }
      }
    return false;
  }
} // namespace rollnip
