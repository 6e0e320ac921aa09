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
      double largest = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() &&
                face->boundary_id() == SliceIds::inner_arc)
              for (unsigned int v = 0; v < face->n_vertices(); ++v)
                {
                  const double deflection = core.value(face->vertex(v)[2]);
                  bonded[face->vertex_dof_index(v, 0)] = deflection;
                  largest = std::max(largest, std::abs(deflection));
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
