#include <deal.II/base/array_view.h>
#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/numerics/data_out.h>

#include <rollnip/three_d/axial_grading.h>
#include <rollnip/three_d/slice_body.h>

#include <cmath>

namespace rollnip
{
  namespace three_d
  {
    std::vector<std::pair<double, double>>
    SliceBody::line_load_profile() const
    {
      // Plane j of nodes at z_j; its share of the face is half the layers
      // on either side (axial_grading.h).
      const std::vector<double> z = axial_planes(three_d.slice_thickness,
                                                 three_d.layers,
                                                 three_d.axial_grading);
      const unsigned int        n = three_d.layers;
      std::vector<double>       f(n + 1, 0.);
      for (const auto &[x_dof, node] : surface)
        if (active.count(x_dof) && owned.is_element(x_dof))
          f[nearest_plane(z, node.X[2])] += reactions[x_dof];
      const std::vector<double> local = f;
      Utilities::MPI::sum(ArrayView<const double>(local),
                          communicator,
                          ArrayView<double>(f));
      std::vector<std::pair<double, double>> profile;
      for (unsigned int j = 0; j <= n; ++j)
        {
          const double width =
            ((j < n ? z[j + 1] : z[j]) - (j > 0 ? z[j - 1] : z[j])) / 2.;
          profile.emplace_back(z[j], -2. * f[j] / width);
        }
      return profile;
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
      out.build_patches();
      out.write_vtu_with_pvtu_record(
        directory + "/", name, counter, communicator, 2);
    }
  } // namespace three_d
} // namespace rollnip
