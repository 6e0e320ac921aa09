#include <deal.II/base/multithread_info.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/data_out.h>

#include <rollnip/boundary_ids.h>
#include <rollnip/fe_fields.h>
#include <rollnip/geometry/angles.h>
#include <rollnip/loading/pressure_load.h>
#include <rollnip/output/atomic_file.h>
#include <rollnip/output/output_writer.h>
#include <rollnip/postprocess/body_values.h>
#include <rollnip/postprocess/stress_postprocessor.h>

#include <iomanip>

namespace rollnip
{
  namespace
  {
    /// DataOut whose patches can be turned half a turn about a point: the
    /// mating roll in the first roll's frame. A half turn negates vectors
    /// and leaves tensors (and so every stress and strain) unchanged.
    class PlacedDataOut : public DataOut<dim>
    {
    public:
      void
      turn_half_about(const Point<dim> &centre)
      {
        std::vector<unsigned int> vector_rows;
        for (const auto &range : this->get_nonscalar_data_ranges())
          if (std::get<3>(range) ==
              DataComponentInterpretation::component_is_part_of_vector)
            for (unsigned int c = std::get<0>(range); c <= std::get<1>(range);
                 ++c)
              vector_rows.push_back(c);
        for (auto &patch : this->patches)
          {
            for (auto &v : patch.vertices)
              v = Point<dim>(2. * centre - v);
            for (const unsigned int c : vector_rows)
              for (unsigned int j = 0; j < patch.data.n_cols(); ++j)
                patch.data(c, j) = -patch.data(c, j);
            // Coordinates of curved patches, in the last dim rows.
            if (patch.points_are_available)
              for (unsigned int d = 0; d < dim; ++d)
                {
                  const unsigned int row = patch.data.n_rows() - dim + d;
                  for (unsigned int j = 0; j < patch.data.n_cols(); ++j)
                    patch.data(row, j) = 2 * centre[d] - patch.data(row, j);
                }
          }
      }
    };

    std::string
    padded(const unsigned int n, const unsigned int width)
    {
      return Utilities::int_to_string(n, width);
    }

    /// The area-weighted average of the cell means of q at every vertex,
    /// on the Q1 space of @p dof_smooth, for smooth plots.
    TrilinosWrappers::MPI::Vector
    smoothed_pressure(const RollBody &body, const DoFHandler<dim> &dof_smooth)
    {
      const MPI_Comm                comm = body.communicator();
      TrilinosWrappers::MPI::Vector sum(dof_smooth.locally_owned_dofs(), comm);
      TrilinosWrappers::MPI::Vector weight(sum);
      const QGauss<dim>   quadrature = FEFields::cell_quadrature(body.fe());
      FEValues<dim>       fe_values(body.mapping(),
                              body.fe(),
                              quadrature,
                              update_values | update_JxW_values);
      std::vector<double> qv(quadrature.size());
      const auto         &pressure_unknown = FEFields::pressure;
      std::vector<types::global_dof_index> idx(
        dof_smooth.get_fe().n_dofs_per_cell());
      auto smooth_cell = dof_smooth.begin_active();
      for (const auto &cell : body.dofs().active_cell_iterators())
        {
          if (cell->is_locally_owned())
            {
              fe_values.reinit(cell);
              fe_values[pressure_unknown].get_function_values(body.solution(),
                                                              qv);
              double area = 0, integral = 0;
              for (unsigned int k = 0; k < quadrature.size(); ++k)
                {
                  area += fe_values.JxW(k);
                  integral += qv[k] * fe_values.JxW(k);
                }
              smooth_cell->get_dof_indices(idx);
              for (const auto i : idx)
                {
                  sum.add(std::vector<types::global_dof_index>{i},
                          std::vector<double>{integral});
                  weight.add(std::vector<types::global_dof_index>{i},
                             std::vector<double>{area});
                }
            }
          ++smooth_cell;
        }
      sum.compress(VectorOperation::add);
      weight.compress(VectorOperation::add);
      for (const auto i : dof_smooth.locally_owned_dofs())
        sum[i] = sum[i] / weight[i];
      sum.compress(VectorOperation::insert);
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dof_smooth, relevant);
      TrilinosWrappers::MPI::Vector smooth(dof_smooth.locally_owned_dofs(),
                                           relevant,
                                           comm);
      smooth = sum;
      return smooth;
    }
  } // namespace

  OutputWriter::OutputWriter(const Parameters::AllParameters &parameters,
                             const MPI_Comm                   mpi_communicator,
                             TimerOutput                     &timer)
      : parameters(parameters)
      , mpi_communicator(mpi_communicator)
      , timer(timer)
      , directory(parameters.output.directory)
  {}

  void
  OutputWriter::set_directory(const std::string &new_directory)
  {
    if (new_directory != directory)
      pvd_records.clear();
    directory = new_directory;
  }

  void
  OutputWriter::set_placement(const std::optional<Point<dim>> &centre)
  {
    placement = centre;
  }

  void
  OutputWriter::write_vtu(const RollBody    &body,
                          const unsigned int step,
                          const double       load_fraction)
  {
    TimerOutput::Scope t(timer, "output");
    const unsigned int rank =
      Utilities::MPI::this_mpi_process(mpi_communicator);
    if (rank == 0)
      make_directories(directory);
    MPI_Barrier(mpi_communicator);

    FE_Q<dim>       fe_smooth(1);
    DoFHandler<dim> dof_smooth(body.mesh());
    dof_smooth.distribute_dofs(fe_smooth);
    const TrilinosWrappers::MPI::Vector smooth =
      smoothed_pressure(body, dof_smooth);

    Vector<float> layer(body.mesh().n_active_cells());
    Vector<float> subdomain(body.mesh().n_active_cells());
    for (const auto &cell : body.mesh().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          layer(cell->active_cell_index())     = cell->material_id();
          subdomain(cell->active_cell_index()) = rank;
        }

    StressPostprocessor postprocessor(body.materials());
    PlacedDataOut       data_out;
    data_out.attach_dof_handler(body.dofs());
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     DataComponentInterpretation::component_is_part_of_vector);
    interpretation.push_back(DataComponentInterpretation::component_is_scalar);
    data_out.add_data_vector(body.solution(),
                             std::vector<std::string>{"displacement",
                                                      "displacement",
                                                      "pressure_unknown_q"},
                             DataOut<dim>::type_dof_data,
                             interpretation);
    data_out.add_data_vector(body.solution(), postprocessor);
    data_out.add_data_vector(dof_smooth, smooth, "pressure_unknown_q_smoothed");
    data_out.add_data_vector(layer, "material_id");
    data_out.add_data_vector(subdomain, "subdomain");
    data_out.build_patches(body.mapping(),
                           body.fe().degree,
                           DataOut<dim>::curved_inner_cells);
    if (placement)
      data_out.turn_half_about(*placement);

    const std::string base = "solution-" + padded(step, 4);
    write_atomically(directory + "/" + base + "." + padded(rank, 4) + ".vtu",
                     [&](std::ostream &out) { data_out.write_vtu(out); });
    MPI_Barrier(mpi_communicator);
    pvd_records.emplace_back(load_fraction, base + ".pvtu");
    if (rank == 0)
      {
        std::vector<std::string> pieces;
        for (unsigned int r = 0;
             r < Utilities::MPI::n_mpi_processes(mpi_communicator);
             ++r)
          pieces.push_back(base + "." + padded(r, 4) + ".vtu");
        write_atomically(directory + "/" + base + ".pvtu",
                         [&](std::ostream &out) {
                           data_out.write_pvtu_record(out, pieces);
                         });
        write_atomically(directory + "/solution.pvd", [&](std::ostream &out) {
          DataOutBase::write_pvd_record(out, pvd_records);
        });
      }
    dof_smooth.clear();
  }

  void
  OutputWriter::write_results(const RollBody      &body,
                              const RunStatistics &statistics,
                              const RunStatus     &status) const
  {
    // Collective: every rank takes part, rank 0 writes.
    const SurfaceData    data      = surface_data(body, status.load_fraction);
    const Tensor<1, dim> resultant = load_resultant(body, status.load_fraction);
    const double         u_r = radial_displacement_on_line_of_centres(body);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    make_directories(directory);
    // No TimerOutput::Scope here: its timer is collective and only rank 0
    // gets this far.
    if (parameters.output.write_csv)
      {
        write_surface_csv(data, "");
        write_logs(statistics);
      }
    write_summary(body, statistics, status, data, resultant, u_r);
  }

  void
  OutputWriter::write_surface_csv(const SurfaceData &data,
                                  const std::string &suffix) const
  {
    constexpr double deg = degrees_per_radian;
    make_directories(directory);
    write_atomically(
      directory + "/outer_surface" + suffix + ".csv", [&](std::ostream &out) {
        out << "theta_deg,X_mm,Y_mm,x_mm,y_mm,u_r_mm,u_theta_mm,"
               "applied_pressure_MPa,normal_pressure_MPa,shear_traction_MPa\n"
            << std::setprecision(10);
        for (const auto &p : data.outer)
          out << p.theta * deg << ',' << p.X << ',' << p.Y << ',' << p.x << ','
              << p.y << ',' << p.u_r << ',' << p.u_theta << ','
              << p.applied_pressure << ',' << p.normal_pressure << ','
              << p.shear_traction << '\n';
      });
    write_atomically(
      directory + "/bond_surface" + suffix + ".csv", [&](std::ostream &out) {
        out << "theta_deg,sigma_rr_MPa,sigma_rtheta_MPa,sigma_thetatheta_MPa,"
               "sigma_zz_MPa\n"
            << std::setprecision(10);
        for (const auto &p : data.bond)
          out << p.theta * deg << ',' << p.sigma_rr << ',' << p.sigma_rtheta
              << ',' << p.sigma_thetatheta << ',' << p.sigma_zz << '\n';
      });
    // Interface j lies between layers j and j + 1, counted from the core.
    for (unsigned int j = 0; j < data.interfaces.size(); ++j)
      write_atomically(directory + "/interface_" + std::to_string(j + 1) +
                         suffix + ".csv",
                       [&](std::ostream &out) {
                         out << "theta_deg,sigma_nn_MPa,sigma_nt_MPa,"
                                "sigma_thetatheta_inner_MPa,"
                                "sigma_thetatheta_outer_MPa\n"
                             << std::setprecision(10);
                         for (const auto &p : data.interfaces[j])
                           out << p.theta * deg << ',' << p.sigma_nn << ','
                               << p.sigma_nt << ',' << p.sigma_thetatheta_inner
                               << ',' << p.sigma_thetatheta_outer << '\n';
                       });
  }

  void
  OutputWriter::write_logs(const RunStatistics &statistics) const
  {
    write_atomically(directory + "/load_steps.csv", [&](std::ostream &out) {
      out << "step,load_fraction,newton_iterations,residual,nip_load_N_per_mm,"
             "u_r_centre_mm,wall_time_s\n"
          << std::setprecision(10);
      for (const auto &r : statistics.steps)
        out << r.step << ',' << r.load_fraction << ',' << r.newton_iterations
            << ',' << r.residual << ',' << r.nip_load << ',' << r.u_r_centre
            << ',' << r.wall_time << '\n';
    });
    write_atomically(directory + "/newton_log.csv", [&](std::ostream &out) {
      out << "step,iteration,load_fraction,residual,constraint,increment,"
             "step_length\n"
          << std::setprecision(10);
      for (const auto &r : statistics.newton)
        out << r.step << ',' << r.iteration << ',' << r.load_fraction << ','
            << r.residual << ',' << r.constraint << ',' << r.increment << ','
            << r.step_length << '\n';
    });
  }

  std::string
  OutputWriter::applied_pressure_line() const
  {
    // An expression in degrees shows as a load on the whole arc.
    if (parameters.contact.mode != Parameters::ContactMode::none ||
        parameters.boundary_conditions.condition[BoundaryIds::outer_arc] !=
          Parameters::BoundaryCondition::pressure)
      return "";
    const std::string d =
      PressureLoad(parameters.load, parameters.geometry).describe();
    return "applied_pressure = " + d.substr(d.find(':') + 2) + '\n';
  }
} // namespace rollnip
