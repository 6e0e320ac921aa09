#include <deal.II/base/multithread_info.h>

#include <rollnip/boundary_ids.h>
#include <rollnip/engineering_inputs.h>
#include <rollnip/output/atomic_file.h>
#include <rollnip/output/output_writer.h>

#include <iomanip>

namespace rollnip
{
  namespace
  {
    /// The lines of how the run went: discretisation, counters, times.
    void
    write_run_lines(std::ostream                    &out,
                    const RollBody                  &body,
                    const RunStatistics             &s,
                    const Parameters::AllParameters &parameters)
    {
      unsigned int n_newton = 0;
      for (const auto &step : s.steps)
        n_newton += step.newton_iterations;
      auto time = [&](const std::string &name) {
        const auto it = s.times.find(name);
        return it == s.times.end() ? 0. : it->second;
      };
      out << "theory = "
          << (body.materials().is_linear() ? "linear" : "nonlinear") << '\n'
          << EngineeringInputs::summary_entries(parameters)
          << "element = " << body.fe().get_name() << '\n'
          << "cells = " << body.n_cells() << '\n'
          << "dofs = " << body.n_dofs() << '\n'
          << "layers = " << body.materials().n_layers() << '\n'
          << "mpi_processes = "
          << Utilities::MPI::n_mpi_processes(body.communicator()) << '\n'
          << "load_steps = " << s.steps.size() << '\n'
          << "newton_iterations = " << n_newton << '\n'
          << "cutbacks = " << s.cutbacks << '\n'
          << "chord_steps = " << s.chord_steps << '\n'
          << "assemblies = " << s.assemblies << '\n'
          << "linear_solves = " << s.linear_solves << '\n'
          << "symbolic_factorisations = " << s.symbolic_factorisations << '\n'
          << "linear_method = " << parameters.linear_solver.method << '\n'
          << "gmres_iterations = " << s.gmres_iterations << '\n'
          << "gmres_solves = " << s.gmres_solves << '\n'
          << "threads = " << MultithreadInfo::n_threads() << '\n'
          << "wall_time_s = " << s.run_wall_time << '\n'
          << "last_solve_wall_time_s = " << s.last_solve_wall_time << '\n'
          << "time_setup_s = " << time("setup") << '\n'
          << "time_assembly_s = "
          << time("assembly") + time("assembly (residual)") << '\n'
          << "time_linear_solve_s = " << time("linear solve") << '\n'
          << "time_output_s = " << time("output") << '\n';
    }

    /// The lines of the results: load, indentation, pressures, stresses.
    void
    write_result_lines(std::ostream         &out,
                       const SurfaceData    &data,
                       const Tensor<1, dim> &R,
                       const double          u_r,
                       const bool            two_sided)
    {
      double peak_applied = 0, peak_normal = 0;
      for (const auto &p : data.outer)
        {
          peak_applied = std::max(peak_applied, p.applied_pressure);
          peak_normal  = std::max(peak_normal, p.normal_pressure);
        }
      const BondExtremes bond = bond_extremes(data.bond);
      const auto        &e    = data.extremes;
      out << "load_resultant_x_N_per_mm = " << R[0] << '\n'
          << "load_resultant_y_N_per_mm = " << R[1] << '\n'
          << "nip_load_P_N_per_mm = " << (two_sided ? -2. : -1.) * R[0] << '\n';
      out << "u_r_at_R0_0_mm = " << u_r << '\n'
          << "indentation_u0_mm = " << -u_r << '\n'
          << "peak_applied_pressure_MPa = " << peak_applied << '\n'
          << "peak_normal_pressure_from_stress_MPa = " << peak_normal << '\n'
          << "bond_sigma_rr_min_MPa = " << bond.sigma_rr_min << '\n'
          << "bond_sigma_rr_max_MPa = " << bond.sigma_rr_max << '\n'
          << "bond_sigma_rtheta_max_abs_MPa = " << bond.sigma_rtheta_max_abs
          << '\n'
          << "sigma_rr_min_MPa = " << e.min_sigma_rr << '\n'
          << "sigma_rr_max_MPa = " << e.max_sigma_rr << '\n'
          << "sigma_rtheta_max_abs_MPa = " << e.max_abs_sigma_rtheta << '\n'
          << "von_mises_max_MPa = " << e.max_von_mises << '\n'
          << "max_principal_stretch = " << e.max_principal_stretch << '\n'
          << "min_principal_stretch = " << e.min_principal_stretch << '\n'
          << "max_principal_strain = " << e.max_principal_stretch - 1. << '\n'
          << "min_J_gauss = " << e.min_J << '\n'
          << "max_abs_J_minus_1_gauss = " << e.max_abs_J_minus_1 << '\n';
      for (unsigned int j = 0; j < data.interfaces.size(); ++j)
        {
          // The traction in the deformed interface's frame (InterfacePoint).
          std::vector<BondSurfacePoint> as_bond;
          for (const auto &p : data.interfaces[j])
            as_bond.push_back({p.theta, p.sigma_nn, p.sigma_nt, 0., 0.});
          const BondExtremes x   = bond_extremes(as_bond);
          const std::string  key = "interface_" + std::to_string(j + 1);
          out << key << "_sigma_nn_min_MPa = " << x.sigma_rr_min << '\n'
              << key << "_sigma_nn_max_MPa = " << x.sigma_rr_max << '\n'
              << key << "_sigma_nt_max_abs_MPa = " << x.sigma_rtheta_max_abs
              << '\n';
        }
    }
  } // namespace

  /**
   * summary.txt: 'key = value' lines, one scalar each, the unit in the key.
   * Written for a finished run and for one that stopped (then describing
   * the last converged step).
   */
  void
  OutputWriter::write_summary(const RollBody       &body,
                              const RunStatistics  &statistics,
                              const RunStatus      &status,
                              const SurfaceData    &data,
                              const Tensor<1, dim> &resultant,
                              const double          u_r) const
  {
    const bool two_sided =
      parameters.boundary_conditions.condition[BoundaryIds::symmetry_edge] ==
      Parameters::BoundaryCondition::symmetry;
    write_atomically(directory + "/summary.txt", [&](std::ostream &out) {
      out << std::setprecision(8);
      out << "# rollnip summary (lengths mm, stresses MPa, loads N/mm)\n";
      out << "status = " << (status.converged ? "converged" : "stopped")
          << '\n';
      if (!status.converged)
        out << "stopped_because = " << status.message << '\n';
      out << "load_fraction = " << status.load_fraction << '\n';
      write_run_lines(out, body, statistics, parameters);
      out << applied_pressure_line();
      write_result_lines(out, data, resultant, u_r, two_sided);
    });
  }
} // namespace rollnip
