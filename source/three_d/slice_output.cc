#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/numerics/data_out.h>

#include <rollnip/three_d/slice_body.h>

namespace rollnip
{
  namespace three_d
  {
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
