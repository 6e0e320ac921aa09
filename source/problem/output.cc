#include <deal.II/base/multithread_info.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/data_out.h>

#include <rollnip/boundary_ids.h>
#include <rollnip/engineering_inputs.h>
#include <rollnip/loading/pressure_load.h>
#include <rollnip/output/atomic_file.h>
#include <rollnip/postprocess/stress_postprocessor.h>
#include <rollnip/problem.h>

#include <filesystem>
#include <iomanip>
#include <limits>

namespace rollnip
{
  namespace
  {
    std::string
    padded(const unsigned int n, const unsigned int width)
    {
      return Utilities::int_to_string(n, width);
    }
  } // namespace

  /**
   * VTU of the current state: displacement, the pressure unknown q (cellwise
   * for Q1-P0) and a nodal average of it for smooth plots, the derived
   * stresses and strains of StressPostprocessor, and the material id. One
   * .vtu per rank, a .pvtu per step and one .pvd for the history.
   */
  void
  RollProblem::write_vtu(const unsigned int step, const double load_fraction)
  {
    TimerOutput::Scope t(timer, "output");
    const std::string &dir = output_directory;
    const unsigned int rank =
      Utilities::MPI::this_mpi_process(mpi_communicator);
    if (rank == 0)
      make_directories(dir);
    MPI_Barrier(mpi_communicator);

    // Smoothed pressure: area-weighted average of the cell means of q.
    FE_Q<dim>       fe_smooth(1);
    DoFHandler<dim> dof_smooth(triangulation);
    dof_smooth.distribute_dofs(fe_smooth);
    IndexSet relevant_smooth;
    DoFTools::extract_locally_relevant_dofs(dof_smooth, relevant_smooth);
    TrilinosWrappers::MPI::Vector sum(dof_smooth.locally_owned_dofs(),
                                      mpi_communicator);
    TrilinosWrappers::MPI::Vector weight(sum);
    {
      const QGauss<dim>                    quadrature(fe->degree + 1);
      FEValues<dim>                        fe_values(*mapping,
                              *fe,
                              quadrature,
                              update_values | update_JxW_values);
      std::vector<double>                  qv(quadrature.size());
      const FEValuesExtractors::Scalar     pressure_unknown(dim);
      std::vector<types::global_dof_index> idx(fe_smooth.n_dofs_per_cell());
      auto smooth_cell = dof_smooth.begin_active();
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (cell->is_locally_owned())
            {
              fe_values.reinit(cell);
              fe_values[pressure_unknown].get_function_values(
                locally_relevant_solution, qv);
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
    }
    TrilinosWrappers::MPI::Vector smooth(dof_smooth.locally_owned_dofs(),
                                         relevant_smooth,
                                         mpi_communicator);
    smooth = sum;

    Vector<float> material_id(triangulation.n_active_cells());
    Vector<float> subdomain(triangulation.n_active_cells());
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          material_id(cell->active_cell_index()) = cell->material_id();
          subdomain(cell->active_cell_index())   = rank;
        }

    StressPostprocessor postprocessor(material);
    DataOut<dim>        data_out;
    data_out.attach_dof_handler(dof_handler);
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     DataComponentInterpretation::component_is_part_of_vector);
    interpretation.push_back(DataComponentInterpretation::component_is_scalar);
    data_out.add_data_vector(locally_relevant_solution,
                             std::vector<std::string>{"displacement",
                                                      "displacement",
                                                      "pressure_unknown_q"},
                             DataOut<dim>::type_dof_data,
                             interpretation);
    data_out.add_data_vector(locally_relevant_solution, postprocessor);
    data_out.add_data_vector(dof_smooth, smooth, "pressure_unknown_q_smoothed");
    data_out.add_data_vector(material_id, "material_id");
    data_out.add_data_vector(subdomain, "subdomain");
    data_out.build_patches(*mapping,
                           fe->degree,
                           DataOut<dim>::curved_inner_cells);

    const std::string base  = "solution-" + padded(step, 4);
    const std::string piece = base + "." + padded(rank, 4) + ".vtu";
    write_atomically(dir + "/" + piece,
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
        write_atomically(dir + "/" + base + ".pvtu", [&](std::ostream &out) {
          data_out.write_pvtu_record(out, pieces);
        });
        write_atomically(dir + "/solution.pvd", [&](std::ostream &out) {
          DataOutBase::write_pvd_record(out, pvd_records);
        });
      }
    dof_smooth.clear();
  }

  void
  RollProblem::write_results(const RunStatus &status)
  {
    // Collective: every rank takes part, rank 0 writes.
    const SurfaceData    data      = surface_data(status.load_fraction);
    const Tensor<1, dim> resultant = load_resultant(status.load_fraction);
    const double         u_r       = radial_displacement_on_line_of_centres();
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    make_directories(output_directory);
    // No TimerOutput::Scope here: its timer is collective and only rank 0
    // gets this far.
    if (parameters.output.write_csv)
      write_csv(data);
    write_summary(status, data, resultant, u_r);
  }

  void
  RollProblem::write_surface_csv(const SurfaceData &data,
                                 const std::string &suffix) const
  {
    const std::string &dir = output_directory;
    constexpr double   deg = 180. / numbers::PI;
    make_directories(dir);
    write_atomically(
      dir + "/outer_surface" + suffix + ".csv", [&](std::ostream &out) {
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
      dir + "/bond_surface" + suffix + ".csv", [&](std::ostream &out) {
        out << "theta_deg,sigma_rr_MPa,sigma_rtheta_MPa,sigma_thetatheta_MPa,"
               "sigma_zz_MPa\n"
            << std::setprecision(10);
        for (const auto &p : data.bond)
          out << p.theta * deg << ',' << p.sigma_rr << ',' << p.sigma_rtheta
              << ',' << p.sigma_thetatheta << ',' << p.sigma_zz << '\n';
      });
  }

  void
  RollProblem::write_csv(const SurfaceData &data) const
  {
    const std::string &dir = output_directory;
    write_surface_csv(data, "");
    write_atomically(dir + "/load_steps.csv", [&](std::ostream &out) {
      out << "step,load_fraction,newton_iterations,residual,nip_load_N_per_mm,"
             "u_r_centre_mm,wall_time_s\n"
          << std::setprecision(10);
      for (const auto &r : step_records)
        out << r.step << ',' << r.load_fraction << ',' << r.newton_iterations
            << ',' << r.residual << ',' << r.nip_load << ',' << r.u_r_centre
            << ',' << r.wall_time << '\n';
    });
    write_atomically(dir + "/newton_log.csv", [&](std::ostream &out) {
      out << "step,iteration,load_fraction,residual,constraint,increment,"
             "step_length\n"
          << std::setprecision(10);
      for (const auto &r : newton_records)
        out << r.step << ',' << r.iteration << ',' << r.load_fraction << ','
            << r.residual << ',' << r.constraint << ',' << r.increment << ','
            << r.step_length << '\n';
    });
  }

  /**
   * summary.txt: 'key = value' lines, one scalar each, the unit in the key.
   * Written for a finished run and for one that stopped (then describing
   * the last converged step).
   */
  void
  RollProblem::write_summary(const RunStatus      &status,
                             const SurfaceData    &data,
                             const Tensor<1, dim> &R,
                             const double          u_r) const
  {
    const bool two_sided =
      parameters.boundary_conditions.condition[BoundaryIds::symmetry_edge] ==
      Parameters::BoundaryCondition::symmetry;
    double peak_applied = 0, peak_normal = 0;
    for (const auto &p : data.outer)
      {
        peak_applied = std::max(peak_applied, p.applied_pressure);
        peak_normal  = std::max(peak_normal, p.normal_pressure);
      }
    const BondExtremes bond        = bond_extremes(data.bond);
    const double       bond_rr_min = bond.sigma_rr_min;
    const double       bond_rr_max = bond.sigma_rr_max;
    const double       bond_rt     = bond.sigma_rtheta_max_abs;
    unsigned int       n_newton    = 0;
    for (const auto &s : step_records)
      n_newton += s.newton_iterations;
    const auto times = timer.get_summary_data(TimerOutput::total_wall_time);
    auto       time  = [&](const std::string &name) {
      const auto it = times.find(name);
      return it == times.end() ? 0. : it->second;
    };
    const auto &e = data.extremes;

    // Where the applied pressure acts (pressure scenes): an expression in
    // degrees shows as a load on the whole arc.
    auto applied_pressure_line = [&]() -> std::string {
      if (parameters.contact.mode != Parameters::ContactMode::none ||
          parameters.boundary_conditions.condition[BoundaryIds::outer_arc] !=
            Parameters::BoundaryCondition::pressure)
        return "";
      const std::string d =
        PressureLoad(parameters.load, parameters.geometry).describe();
      return "applied_pressure = " + d.substr(d.find(':') + 2) + '\n';
    };
    write_atomically(output_directory + "/summary.txt", [&](std::ostream &out) {
      out << std::setprecision(8);
      out << "# rollnip summary (lengths mm, stresses MPa, loads N/mm)\n";
      out << "status = " << (status.converged ? "converged" : "stopped")
          << '\n';
      if (!status.converged)
        out << "stopped_because = " << status.message << '\n';
      out << "theory = " << (material.is_linear() ? "linear" : "nonlinear")
          << '\n'
          << EngineeringInputs::summary_entries(parameters)
          << "element = " << fe->get_name() << '\n'
          << "cells = " << triangulation.n_global_active_cells() << '\n'
          << "dofs = " << dof_handler.n_dofs() << '\n'
          << "mpi_processes = "
          << Utilities::MPI::n_mpi_processes(mpi_communicator) << '\n'
          << "load_fraction = " << status.load_fraction << '\n'
          << "load_steps = " << step_records.size() << '\n'
          << "newton_iterations = " << n_newton << '\n'
          << "cutbacks = " << n_cutbacks << '\n'
          << "assemblies = " << n_assemblies << '\n'
          << "linear_solves = " << n_linear_solves << '\n'
          << "symbolic_factorisations = " << direct_solver.n_analyses << '\n'
          << "linear_method = " << parameters.linear_solver.method << '\n'
          << "gmres_iterations = " << iterative_solver.n_iterations << '\n'
          << "gmres_solves = " << iterative_solver.n_solves << '\n'
          << "threads = " << MultithreadInfo::n_threads() << '\n'
          << "load_resultant_x_N_per_mm = " << R[0] << '\n'
          << "load_resultant_y_N_per_mm = " << R[1] << '\n'
          << "nip_load_P_N_per_mm = " << (two_sided ? -2. : -1.) * R[0] << '\n'
          << applied_pressure_line() << "u_r_at_R0_0_mm = " << u_r << '\n'
          << "indentation_u0_mm = " << -u_r << '\n'
          << "peak_applied_pressure_MPa = " << peak_applied << '\n'
          << "peak_normal_pressure_from_stress_MPa = " << peak_normal << '\n'
          << "bond_sigma_rr_min_MPa = " << bond_rr_min << '\n'
          << "bond_sigma_rr_max_MPa = " << bond_rr_max << '\n'
          << "bond_sigma_rtheta_max_abs_MPa = " << bond_rt << '\n'
          << "sigma_rr_min_MPa = " << e.min_sigma_rr << '\n'
          << "sigma_rr_max_MPa = " << e.max_sigma_rr << '\n'
          << "sigma_rtheta_max_abs_MPa = " << e.max_abs_sigma_rtheta << '\n'
          << "von_mises_max_MPa = " << e.max_von_mises << '\n'
          << "max_principal_stretch = " << e.max_principal_stretch << '\n'
          << "min_principal_stretch = " << e.min_principal_stretch << '\n'
          << "max_principal_strain = " << e.max_principal_stretch - 1. << '\n'
          << "min_J_gauss = " << e.min_J << '\n'
          << "max_abs_J_minus_1_gauss = " << e.max_abs_J_minus_1 << '\n'
          << "wall_time_s = " << wall_clock.wall_time() << '\n'
          << "time_setup_s = " << time("setup") << '\n'
          << "time_assembly_s = "
          << time("assembly") + time("assembly (residual)") << '\n'
          << "time_linear_solve_s = " << time("linear solve") << '\n'
          << "time_output_s = " << time("output") << '\n';
    });
  }
} // namespace rollnip
