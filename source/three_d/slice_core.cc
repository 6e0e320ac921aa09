#include <rollnip/three_d/slice_body.h>

#include <cmath>

namespace rollnip
{
  namespace three_d
  {
    void
    SliceBody::collect_bonded_nodes()
    {
      if (core.is_zero())
        return;
      using BC       = Parameters::BoundaryCondition;
      const auto &bc = parameters.boundary_conditions.condition;
      // The core moves along x1: a fixed far edge, or the symmetry plane
      // x1 = 0 of a 90 deg sector, would hold the cover's edge against it.
      AssertThrow(bc[SliceIds::far_edge] == BC::free ||
                    (bc[SliceIds::far_edge] == BC::symmetry &&
                     std::abs(parameters.geometry.sector_angle - numbers::PI) <
                       1e-12),
                  ExcMessage("Three d/Core deflection needs Boundary "
                             "conditions/Far edge = free, or symmetry with a "
                             "sector angle of 180 deg (the core moves along "
                             "x1)"));
      // Every node of the bond, Q2's edge and face nodes too: the bent
      // core carries all the displacement dofs at R1.
      double largest = 0;
      for (const auto &[x_dof, node] : boundary_nodes(SliceIds::inner_arc))
        {
          const double deflection = core.value(node.X[2]);
          bonded[x_dof]           = deflection;
          largest                 = std::max(largest, std::abs(deflection));
        }
      core_amplitude = Utilities::MPI::max(largest, communicator);
    }

    void
    SliceBody::add_core_displacement(AffineConstraints<double> &c) const
    {
      // The update takes u_x from its current value to -factor v.
      for (const auto &[x_dof, deflection] : bonded)
        c.set_inhomogeneity(x_dof, -core_factor * deflection - solution[x_dof]);
    }
  } // namespace three_d
} // namespace rollnip
