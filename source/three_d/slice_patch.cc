#include <rollnip/output/atomic_file.h>
#include <rollnip/three_d/slice_body.h>

#include <iomanip>

#include <cmath>
#include <limits>

namespace rollnip
{
  namespace three_d
  {
    void
    SliceBody::collect_surface_faces()
    {
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() &&
                face->boundary_id() == SliceIds::outer_arc)
              {
                std::array<types::global_dof_index, 4> dofs;
                for (unsigned int v = 0; v < 4; ++v)
                  dofs[v] = face->vertex_dof_index(v, 0);
                surface_faces.push_back(dofs);
              }
    }

    TrilinosWrappers::MPI::Vector
    SliceBody::vertex_areas() const
    {
      // Each node's share of the deformed outer surface: a quarter of the
      // area of every face it is a vertex of (half the cross product of
      // the diagonals of the quadrilateral 0-1-3-2).
      TrilinosWrappers::MPI::Vector owned_area(owned, communicator);
      for (const auto &face : surface_faces)
        {
          const Tensor<1, dim> d1 =
            deformed(surface.at(face[3])) - deformed(surface.at(face[0]));
          const Tensor<1, dim> d2 =
            deformed(surface.at(face[2])) - deformed(surface.at(face[1]));
          const double share = 0.125 * cross_product_3d(d1, d2).norm();
          for (const auto dof : face)
            owned_area.add(std::vector<types::global_dof_index>{dof},
                           std::vector<double>{share});
        }
      owned_area.compress(VectorOperation::add);
      TrilinosWrappers::MPI::Vector area(owned, relevant, communicator);
      area = owned_area;
      return area;
    }

    ContactPatch
    SliceBody::contact_patch() const
    {
      const TrilinosWrappers::MPI::Vector area =
        degree == 1 ? vertex_areas() : lumped_areas(SliceIds::outer_arc, true);

      ContactPatch                           patch;
      std::vector<std::pair<double, double>> pressures; ///< (p, z), owned
      const double                           L = three_d.slice_thickness;
      for (const auto x_dof : active)
        {
          const SurfaceNode &node = surface.at(x_dof);
          const Point<dim>   x    = deformed(node);
          if (std::abs(node.X[2]) < 1e-9 * L)
            patch.half_chord_middle = std::max(patch.half_chord_middle, x[1]);
          if (std::abs(node.X[2] - L) < 1e-9 * L)
            patch.half_chord_far = std::max(patch.half_chord_far, x[1]);
          if (!owned.is_element(x_dof))
            continue;
          const Tensor<1, dim> n     = gap_normal(node, current_u0);
          double               force = 0;
          for (unsigned int c = 0; c < dim; ++c)
            force += n[c] * reactions[node.dofs[c]];
          pressures.emplace_back(force / area[x_dof], node.X[2]);
        }
      for (const auto &[p, z] : pressures)
        patch.peak_pressure = std::max(patch.peak_pressure, p);
      patch.peak_pressure =
        Utilities::MPI::max(patch.peak_pressure, communicator);
      // Nodes equal to round-off (a plane-strain slice) tie: the smallest
      // z of the ties, so that every partition names the same node.
      double z_min = std::numeric_limits<double>::max();
      for (const auto &[p, z] : pressures)
        if (p >= (1 - 1e-9) * patch.peak_pressure)
          z_min = std::min(z_min, z);
      patch.peak_z =
        patch.peak_pressure > 0 ? Utilities::MPI::min(z_min, communicator) : 0.;
      patch.half_chord_middle =
        Utilities::MPI::max(patch.half_chord_middle, communicator);
      patch.half_chord_far =
        Utilities::MPI::max(patch.half_chord_far, communicator);
      // consistent_line_load() inverts the mass matrix of linear elements
      // (the layers of Q1, or the stations' hats of a mesh not in layers);
      // Q2's lumped value is exact for a q uniform along the axis.
      patch.line_load_middle =
        degree == 1 || !layered
          ? consistent_line_load(line_load_profile()).front().second
          : line_load_profile().front().second;
      return patch;
    }

    void
    write_contact_patch(const std::string        &path,
                        const ContactPatch       &patch,
                        const SliceNip           &nip,
                        const Parameters::ThreeD &three_d)
    {
      write_atomically(path, [&](std::ostream &out) {
        out << std::setprecision(8)
            << "# rollnip 3D contact patch at the last approach (pressure "
               "over the deformed surface's nodal share)\n"
            << "indentation_u0_mm = " << nip.u0 << '\n'
            << "peak_pressure_MPa = " << patch.peak_pressure << '\n'
            << "peak_pressure_z_mm = " << patch.peak_z << '\n'
            << "half_chord_at_z0_mm = " << patch.half_chord_middle << '\n'
            << "half_chord_at_far_face_mm = " << patch.half_chord_far << '\n'
            << "line_load_at_z0_N_per_mm = " << patch.line_load_middle << '\n'
            << "mean_line_load_N_per_mm = " << nip.P << '\n'
            << "total_force_on_2L_N = " << nip.P * 2 * three_d.slice_thickness
            << '\n';
      });
    }
  } // namespace three_d
} // namespace rollnip
