#include <deal.II/base/array_view.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/numerics/data_out.h>

#include <rollnip/three_d/axial_grading.h>
#include <rollnip/three_d/slice_body.h>

#include <cmath>

namespace rollnip
{
  namespace three_d
  {
    std::vector<double>
    SliceBody::node_planes() const
    {
      const std::vector<double> &z = layer_planes;
      if (degree == 1 || !layered)
        return z;
      std::vector<double> planes = {z.front()};
      for (unsigned int j = 1; j < z.size(); ++j)
        {
          planes.push_back((z[j - 1] + z[j]) / 2.);
          planes.push_back(z[j]);
        }
      return planes;
    }

    std::vector<double>
    SliceBody::line_load_widths() const
    {
      // The row sums of the 1D mass matrix along z: a plane's share of
      // the face, so that sum q_j w_j is the total force.
      const std::vector<double> &z = layer_planes;
      std::vector<double>        widths(node_planes().size(), 0.);
      for (unsigned int j = 0; j + 1 < z.size(); ++j)
        {
          const double h = z[j + 1] - z[j];
          if (degree == 1 || !layered)
            {
              widths[j] += h / 2;
              widths[j + 1] += h / 2;
            }
          else
            {
              widths[2 * j] += h / 6;
              widths[2 * j + 1] += 2 * h / 3;
              widths[2 * j + 2] += h / 6;
            }
        }
      return widths;
    }

    std::vector<std::pair<double, double>>
    SliceBody::line_load_profile() const
    {
      const std::vector<double> planes = node_planes();
      const std::vector<double> widths = line_load_widths();
      std::vector<double>       f(planes.size(), 0.);
      if (layered)
        {
          for (const auto &[x_dof, node] : surface)
            if (active.count(x_dof) && owned.is_element(x_dof))
              f[nearest_plane(planes, node.X[2])] += reactions[x_dof];
        }
      else
        add_station_forces(planes, f);
      const std::vector<double> local = f;
      Utilities::MPI::sum(ArrayView<const double>(local),
                          communicator,
                          ArrayView<double>(f));
      std::vector<std::pair<double, double>> profile;
      for (unsigned int j = 0; j < planes.size(); ++j)
        profile.emplace_back(planes[j], -2. * f[j] / widths[j]);
      return profile;
    }

    void
    SliceBody::add_station_forces(const std::vector<double> &stations,
                                  std::vector<double>       &f) const
    {
      // The contact pressure p_h = sum_i (R_i / a_i) N_i with a_i = int N_i
      // dA, so that int p_h dA = sum_i R_i, integrated against each
      // station's hat. The hats' kinks cross the faces: a finer rule.
      const TrilinosWrappers::MPI::Vector area =
        lumped_areas(SliceIds::outer_arc, false);
      FEFaceValues<dim>                    fv(*mapping,
                           fe,
                           QIterated<dim - 1>(QGauss<1>(degree + 1), 4),
                           update_values | update_quadrature_points |
                             update_JxW_values);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int face : cell->face_indices())
            if (cell->face(face)->at_boundary() &&
                cell->face(face)->boundary_id() == SliceIds::outer_arc)
              {
                fv.reinit(cell, face);
                cell->get_dof_indices(dofs);
                for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
                  {
                    double p = 0;
                    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                      if (fe.system_to_component_index(i).first == 0 &&
                          fe.has_support_on_face(i, face) &&
                          active.count(dofs[i]))
                        p += reactions[dofs[i]] / area[dofs[i]] *
                             fv.shape_value_component(i, q, 0);
                    const auto [j, t] =
                      hat_share(stations, fv.quadrature_point(q)[2]);
                    f[j] += (1 - t) * p * fv.JxW(q);
                    if (t > 0)
                      f[j + 1] += t * p * fv.JxW(q);
                  }
              }
    }

    void
    SliceBody::write_vtu(const std::string &directory,
                         const std::string &name,
                         const unsigned int counter) const
    {
      std::vector<std::string> names(dim, "displacement");
      names.emplace_back("pressure_unknown_q");
      std::vector<DataComponentInterpretation::DataComponentInterpretation>
        kinds(dim, DataComponentInterpretation::component_is_part_of_vector);
      kinds.push_back(DataComponentInterpretation::component_is_scalar);
      DataOut<dim> out;
      out.attach_dof_handler(dof_handler);
      out.add_data_vector(solution, names, DataOut<dim>::type_dof_data, kinds);
      Vector<float> rank(triangulation.n_active_cells());
      rank = Utilities::MPI::this_mpi_process(communicator);
      out.add_data_vector(rank, "mpi_rank");
      out.build_patches(*mapping, degree);
      out.write_vtu_with_pvtu_record(
        directory + "/", name, counter, communicator, 2);
    }
  } // namespace three_d
} // namespace rollnip
