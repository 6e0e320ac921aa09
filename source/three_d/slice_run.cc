#include <deal.II/base/timer.h>

#include <rollnip/output/atomic_file.h>
#include <rollnip/three_d/core_stress.h>
#include <rollnip/three_d/core_tube.h>
#include <rollnip/three_d/free_end.h>
#include <rollnip/three_d/load_control.h>
#include <rollnip/three_d/slice_body.h>
#include <rollnip/three_d/slice_run.h>

#include <iomanip>
#include <iostream>

namespace rollnip
{
  namespace
  {
    void
    write_table(const std::string                    &path,
                const std::vector<three_d::SliceNip> &nips,
                const std::vector<double>            &seconds)
    {
      write_atomically(path, [&](std::ostream &out) {
        out << std::setprecision(10)
            << "u0_mm,P_N_per_mm,half_chord_b_mm,contact_length_mm,"
               "active_nodes,newton_steps,max_penetration_mm,wall_time_s,"
               "gmres_iterations\n";
        for (unsigned int k = 0; k < nips.size(); ++k)
          out << nips[k].u0 << ',' << nips[k].P << ',' << nips[k].half_chord
              << ',' << nips[k].contact_length << ',' << nips[k].active_nodes
              << ',' << nips[k].newton_steps << ',' << nips[k].max_penetration
              << ',' << seconds[k] << ',' << nips[k].linear_iterations << '\n';
      });
    }

    void
    write_summary(const std::string                             &path,
                  const three_d::SliceBody                      &body,
                  const Parameters::AllParameters               &parameters,
                  const Parameters::ThreeD                      &three_d,
                  const three_d::SliceNip                       &nip,
                  const double                                   seconds,
                  const unsigned int                             processes,
                  const three_d::FreeEnd                        *free_end,
                  const std::vector<std::pair<double, double>>  &bending,
                  const std::vector<three_d::CoreBendingStress> &core_stress)
    {
      write_atomically(path, [&](std::ostream &out) {
        out << std::setprecision(8)
            << "# rollnip 3D slice summary (lengths mm, loads N/mm)\n"
            << "status = converged\n"
            << "dimension = 3\n"
            << "element = "
            << (body.displacement_degree() == 1 ? "Q1-P0" : "Q2-P1") << '\n'
            << "mesh_level = " << parameters.mesh.global_refinements << '\n'
            << "n_cells = " << body.n_cells() << '\n'
            << "n_dofs = " << body.n_dofs() << '\n'
            << "mpi_processes = " << processes << '\n'
            << "linear_solver = " << parameters.linear_solver.method << '\n'
            << "symbolic_factorisations = "
            << body.direct_factorisations().first << '\n'
            << "factorisations = " << body.direct_factorisations().second
            << '\n'
            << "slice_thickness_mm = " << three_d.slice_thickness << '\n'
            << "far_face = " << (three_d.fix_far_face ? "fixed axial" : "free")
            << '\n'
            << "indentation_u0_mm = " << nip.u0 << '\n'
            << "nip_load_P_N_per_mm = " << nip.P << '\n'
            << "half_chord_b_mm = " << nip.half_chord << '\n'
            << "contact_length_along_axis_mm = " << nip.contact_length << '\n'
            << "active_nodes = " << nip.active_nodes << '\n'
            << "max_penetration_mm = " << nip.max_penetration << '\n'
            << "wall_time_s = " << seconds << '\n';
        if (free_end)
          three_d::write_free_end_summary(out, *free_end);
        if (!bending.empty()) // the elastic core's v at z = 0 and the end
          out << "core = elastic\n"
              << "core_deflection_middle_mm = " << bending.front().second
              << '\n'
              << "core_deflection_cover_end_mm = "
              << bending[three_d.layers].second << '\n';
        if (!core_stress.empty())
          three_d::write_core_stress_summary(out, core_stress.front());
      });
    }
    /// The screen line of one solved nip.
    void
    print_nip(const three_d::SliceNip &nip, const double seconds)
    {
      std::cout << "  u0 = " << nip.u0 << " mm: P = " << nip.P
                << " N/mm, b = " << nip.half_chord << " mm, "
                << nip.active_nodes << " active nodes, " << nip.newton_steps
                << " Newton steps, "
                << (nip.linear_iterations > 0
                      ? std::to_string(nip.linear_iterations) +
                          " GMRES iterations, "
                      : std::string())
                << seconds << " s" << std::endl;
    }

    /// The line load q(z) [N/mm] at the node planes along the axis.
    template <typename Profile>
    void
    write_line_load(const std::string &path, const Profile &profile)
    {
      write_atomically(path, [&](std::ostream &out) {
        out << std::setprecision(10) << "z_mm,line_load_N_per_mm\n";
        for (const auto &[z, q] : profile)
          out << z << ',' << q << '\n';
      });
    }

    /// The elastic core's deflection v(z) [mm] (core_tube.h) and, on the
    /// screen, its value at the middle of the face.
    void
    write_elastic_core(const std::string                            &path,
                       const std::vector<std::pair<double, double>> &bending)
    {
      write_atomically(path, [&](std::ostream &out) {
        out << std::setprecision(10) << "z_mm,core_deflection_v_mm\n";
        for (const auto &[z, v] : bending)
          out << z << ',' << v << '\n';
      });
      std::cout << "  elastic core: deflection v = " << bending.front().second
                << " mm at the middle of the face, v(z) in " << path
                << std::endl;
    }
    /// The solved nips of a sweep over Contact/Values, their wall times
    /// [s] and, with a free far face, the free end of each.
    struct SliceSweep
    {
      std::vector<three_d::SliceNip> nips;
      std::vector<double>            seconds;
      std::vector<three_d::FreeEnd>  free_ends;
    };

    /// Solves every value of Contact/Values in turn (u0, or P under load
    /// control from the previous nip), printing each nip on @p root and
    /// writing its VTU when asked.
    SliceSweep
    solve_sweep(three_d::SliceBody              &body,
                const Parameters::AllParameters &parameters,
                const Parameters::ThreeD        &three_d,
                const bool                       root)
    {
      const bool load_driven =
        parameters.contact.mode == Parameters::ContactMode::load;
      SliceSweep sweep;
      auto      &nips = sweep.nips;
      for (const double value : parameters.contact.values)
        {
          Timer timer;
          nips.push_back(
            load_driven
              ? three_d::solve_for_load(body,
                                        value,
                                        nips.empty() ? three_d::SliceNip()
                                                     : nips.back(),
                                        three_d.approach_step,
                                        parameters.contact.control_tolerance,
                                        parameters.contact.max_iterations)
              : body.solve(value));
          sweep.seconds.push_back(timer.wall_time());
          if (root)
            print_nip(nips.back(), sweep.seconds.back());
          if (!three_d.fix_far_face && !three_d.elastic_core)
            sweep.free_ends.push_back(
              three_d::evaluate_free_end(body, nips.back().u0));
          if (parameters.output.write_vtu)
            body.write_vtu(parameters.output.directory,
                           "slice_3d",
                           nips.size() - 1);
        }
      return sweep;
    }
  } // namespace

  int
  run_three_d(const Parameters::AllParameters &parameters,
              const Parameters::ThreeD        &three_d,
              MPI_Comm                         communicator)
  {
    const bool root = Utilities::MPI::this_mpi_process(communicator) == 0;
    const std::string &directory = parameters.output.directory;
    Timer              total;
    three_d::SliceBody body(parameters,
                            three_d,
                            parameters.mesh.global_refinements,
                            communicator);
    if (root)
      {
        make_directories(directory);
        std::cout << "3D slice: " << body.n_cells() << " cells, "
                  << body.n_dofs() << " DoFs, " << three_d.slice_thickness
                  << " mm thick" << std::endl
                  << "  linear solver: " << body.linear_solver_name()
                  << std::endl;
      }
    const auto [nips, seconds, free_ends] =
      solve_sweep(body, parameters, three_d, root);
    const auto                  profile     = body.line_load_profile();
    const three_d::ContactPatch patch       = body.contact_patch();
    const auto                  bending     = three_d.elastic_core
                                                ? three_d::core_deflection_profile(body)
                                                : std::vector<std::pair<double, double>>();
    const auto                  core_stress = three_d.elastic_core
                                                ? three_d::core_bending_stress(body)
                                                : std::vector<three_d::CoreBendingStress>();
    if (root)
      {
        if (!bending.empty())
          write_elastic_core(directory + "/core_deflection_along_axis.csv",
                             bending);
        if (!core_stress.empty())
          three_d::write_core_stress(directory +
                                       "/core_bending_stress_along_axis.csv",
                                     core_stress);
        write_line_load(directory + "/line_load_along_axis.csv", profile);
        three_d::write_contact_patch(directory + "/contact_patch.txt",
                                     patch,
                                     nips.back(),
                                     three_d);
        const three_d::CoreDeflection core(three_d.core_deflection);
        if (!core.is_zero())
          three_d::write_core_profile(directory +
                                        "/core_deflection_along_axis.csv",
                                      profile,
                                      core,
                                      nips.back().u0);
        write_table(directory + "/slice_3d.csv", nips, seconds);
        if (!free_ends.empty())
          {
            three_d::write_free_end_table(directory + "/free_end.csv",
                                          free_ends);
            three_d::write_bond_along_axis(directory +
                                             "/bond_traction_along_axis.csv",
                                           free_ends.back());
          }
        write_summary(directory + "/summary.txt",
                      body,
                      parameters,
                      three_d,
                      nips.back(),
                      total.wall_time(),
                      Utilities::MPI::n_mpi_processes(communicator),
                      free_ends.empty() ? nullptr : &free_ends.back(),
                      bending,
                      core_stress);
      }
    return 0;
  }
} // namespace rollnip
