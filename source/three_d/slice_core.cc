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
      // Its far edge was checked with the mesh (check_slice_scene()).
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
