#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>

#include <rollnip/output/atomic_file.h>
#include <rollnip/three_d/core_stress.h>
#include <rollnip/three_d/core_tube.h>
#include <rollnip/three_d/slice_body.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <map>

namespace rollnip
{
  namespace three_d
  {
    namespace
    {
      /// Area-weighted sums over one plane's quadrature points: w, w x,
      /// w x^2, w s, w s x, w s^2 with s = sigma_zz.
      using PlaneSums = std::array<double, 6>;

      /// The sums of every plane of the tube's faces normal to z on this
      /// process, by z [mm]. Every interior plane gets both sides' faces.
      std::map<double, PlaneSums>
      local_plane_sums(const SliceBody &body)
      {
        const auto              &dofs   = body.get_dof_handler();
        const auto              &fe     = dofs.get_fe();
        const unsigned int       degree = body.displacement_degree();
        const MappingQ<dim>      mapping(degree);
        const QGauss<dim - 1>    quadrature(degree + 1);
        FEFaceValues<dim>        values(mapping,
                                 fe,
                                 quadrature,
                                 update_values | update_gradients |
                                   update_quadrature_points |
                                   update_JxW_values);
        const auto               law = make_core_law(body.three_d_parameters());
        const types::material_id core_id =
          body.parameters_of_mesh().material.n_layers();
        const FEValuesExtractors::Vector u_ex(0);
        const FEValuesExtractors::Scalar q_ex(dim);
        std::vector<Tensor<2, dim>>      grad_u(quadrature.size());
        std::vector<double>              q(quadrature.size());
        std::map<double, PlaneSums>      sums;
        const double tol = 1e-9 * body.three_d_parameters().bearing_distance;
        for (const auto &cell : dofs.active_cell_iterators())
          if (cell->is_locally_owned() && cell->material_id() == core_id)
            for (const unsigned int f : cell->face_indices())
              {
                const auto   face = cell->face(f);
                const double z    = face->vertex(0)[2];
                bool         flat = true;
                for (unsigned int v = 1; v < face->n_vertices(); ++v)
                  flat = flat && std::abs(face->vertex(v)[2] - z) < tol;
                if (!flat)
                  continue;
                values.reinit(cell, f);
                values[u_ex].get_function_gradients(body.current_solution(),
                                                    grad_u);
                values[q_ex].get_function_values(body.current_solution(), q);
                // Planes are keyed by z rounded to 1e-6 mm.
                PlaneSums &s = sums[std::round(z * 1e6) / 1e6];
                for (unsigned int k = 0; k < quadrature.size(); ++k)
                  {
                    const double w = values.JxW(k);
                    const double x = values.quadrature_point(k)[0];
                    const double sigma =
                      law->cauchy(unit_symmetric_tensor<dim>() + grad_u[k],
                                  q[k])[2][2];
                    const std::array<double, 6> add = {{w,
                                                        w * x,
                                                        w * x * x,
                                                        w * sigma,
                                                        w * sigma * x,
                                                        w * sigma * sigma}};
                    for (unsigned int i = 0; i < 6; ++i)
                      s[i] += add[i];
                  }
              }
        return sums;
      }

      /// The beam's M(z) [N mm], simply supported at +-@p bearing, under
      /// the nodal forces q_j w_j at the planes z_j >= 0 (and their mirror
      /// images): the journal's reaction sum_j q_j w_j times its lever
      /// less the loads between z and the journal times theirs.
      double
      beam_moment(const std::vector<std::pair<double, double>> &q,
                  const std::vector<double>                    &widths,
                  const double                                  bearing,
                  const double                                  z)
      {
        double M = 0;
        for (unsigned int j = 0; j < q.size(); ++j)
          {
            const double force = q[j].second * widths[j];
            M += force * (bearing - z);
            if (q[j].first > z)
              M -= force * (q[j].first - z);
          }
        return M;
      }
    } // namespace

    std::vector<CoreBendingStress>
    core_bending_stress(const SliceBody &body)
    {
      std::map<double, PlaneSums> sums;
      const auto                  local = local_plane_sums(body);
      for (const auto &part :
           Utilities::MPI::all_gather(body.mpi_communicator(), local))
        for (const auto &[z, s] : part)
          for (unsigned int i = 0; i < 6; ++i)
            sums[z][i] += s[i];
      const auto  &three_d = body.three_d_parameters();
      const double R1      = body.parameters_of_mesh().geometry.inner_radius;
      const double Ri      = three_d.core_inner_radius;
      const double I = numbers::PI / 4. * (std::pow(R1, 4) - std::pow(Ri, 4));
      const auto   q = body.line_load_profile();
      const auto   w = body.line_load_widths();
      std::vector<CoreBendingStress> stresses;
      for (const auto &[z, s] : sums)
        {
          CoreBendingStress c;
          c.z                 = z;
          const double x_mean = s[1] / s[0];
          const double slope  = (s[4] - s[3] * x_mean) / (s[2] - s[1] * x_mean);
          c.mean              = s[3] / s[0] - slope * x_mean;
          const auto at = [&](const double x) { return c.mean + slope * x; };
          c.outer_nip   = at(R1);
          c.outer_far   = at(-R1);
          c.bore_nip    = at(Ri);
          c.bore_far    = at(-Ri);
          c.moment      = beam_moment(q, w, three_d.bearing_distance, z);
          c.beam_outer  = -c.moment * R1 / I;
          c.beam_bore   = -c.moment * Ri / I;
          const double residual = s[5] - c.mean * s[3] - slope * s[4];
          c.deviation           = std::sqrt(std::max(0., residual / s[0]));
          stresses.push_back(c);
        }
      return stresses;
    }

    void
    write_core_stress(const std::string                    &path,
                      const std::vector<CoreBendingStress> &stresses)
    {
      write_atomically(path, [&](std::ostream &out) {
        out << std::setprecision(8)
            << "z_mm,beam_moment_N_mm,sigma_zz_outer_nip_MPa,"
               "beam_sigma_zz_outer_nip_MPa,sigma_zz_bore_nip_MPa,"
               "beam_sigma_zz_bore_nip_MPa,sigma_zz_outer_far_MPa,"
               "sigma_zz_bore_far_MPa,sigma_zz_mean_MPa,"
               "sigma_zz_deviation_rms_MPa\n";
        for (const auto &c : stresses)
          out << c.z << ',' << c.moment << ',' << c.outer_nip << ','
              << c.beam_outer << ',' << c.bore_nip << ',' << c.beam_bore << ','
              << c.outer_far << ',' << c.bore_far << ',' << c.mean << ','
              << c.deviation << '\n';
      });
    }

    void
    write_core_stress_summary(std::ostream            &out,
                              const CoreBendingStress &middle)
    {
      out << "core_bending_moment_middle_beam_N_mm = " << middle.moment << '\n'
          << "core_sigma_zz_outer_fibre_nip_MPa = " << middle.outer_nip << '\n'
          << "core_sigma_zz_outer_fibre_far_MPa = " << middle.outer_far << '\n'
          << "core_sigma_zz_bore_nip_MPa = " << middle.bore_nip << '\n'
          << "core_sigma_zz_bore_far_MPa = " << middle.bore_far << '\n'
          << "core_sigma_zz_outer_fibre_beam_MPa = " << middle.beam_outer
          << '\n'
          << "core_sigma_zz_bore_beam_MPa = " << middle.beam_bore << '\n'
          << "core_sigma_zz_deviation_rms_middle_MPa = " << middle.deviation
          << '\n';
    }
  } // namespace three_d
} // namespace rollnip
