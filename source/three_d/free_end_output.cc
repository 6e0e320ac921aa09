#include <rollnip/output/atomic_file.h>
#include <rollnip/three_d/free_end.h>

#include <iomanip>

namespace rollnip
{
  namespace three_d
  {
    namespace
    {
      /// r [mm], theta [deg] and z [mm] of @p X.
      std::array<double, 3>
      cylindrical(const Point<dim> &X)
      {
        return {{std::hypot(X[0], X[1]),
                 std::atan2(X[1], X[0]) * 180. / numbers::PI,
                 X[2]}};
      }

      void
      write_stress(std::ostream      &out,
                   const std::string &name,
                   const BondStress  &s)
      {
        const auto c = cylindrical(s.where);
        out << name << "_sigma_rr_MPa = " << s.sigma_rr << '\n'
            << name << "_tau_rtheta_MPa = " << s.tau_rtheta << '\n'
            << name << "_tau_rz_MPa = " << s.tau_rz << '\n'
            << name << "_theta_deg = " << c[1] << '\n'
            << name << "_z_mm = " << c[2] << '\n';
      }
    } // namespace

    void
    write_free_end_table(const std::string          &path,
                         const std::vector<FreeEnd> &rows)
    {
      write_atomically(path, [&](std::ostream &out) {
        out << std::setprecision(10)
            << "u0_mm,q_middle_N_per_mm,q_end_N_per_mm,q_mean_N_per_mm,"
               "deficit_length_l_mm,rise_95_mm,rise_99_mm,"
               "end_bulge_uz_mm,bulge_r_mm,bulge_theta_deg,"
               "bond_shear_peak_MPa,bond_shear_peak_z_mm,"
               "bond_shear_middle_MPa,bond_tension_peak_MPa,"
               "bond_tension_peak_z_mm,bond_compression_peak_MPa,"
               "bond_compression_middle_MPa\n";
        for (const FreeEnd &f : rows)
          {
            const auto b = cylindrical(f.bulge_at);
            out << f.u0 << ',' << f.decay.q_far << ',' << f.decay.q_end << ','
                << f.decay.q_mean << ',' << f.decay.deficit_length << ','
                << f.decay.rise_95 << ',' << f.decay.rise_99 << ',' << f.bulge
                << ',' << b[0] << ',' << b[1] << ',' << f.shear_peak.shear()
                << ',' << f.shear_peak.where[2] << ',' << f.shear_middle.shear()
                << ',' << f.tension_peak.sigma_rr << ','
                << f.tension_peak.where[2] << ',' << f.compression_peak.sigma_rr
                << ',' << f.compression_middle.sigma_rr << '\n';
          }
      });
    }

    void
    write_bond_along_axis(const std::string &path, const FreeEnd &result)
    {
      write_atomically(path, [&](std::ostream &out) {
        out << std::setprecision(10)
            << "z_mm,max_abs_tau_rz_MPa,max_bond_shear_MPa,"
               "max_sigma_rr_MPa,min_sigma_rr_MPa\n";
        for (const auto &row : result.bond_along_axis)
          out << row[0] << ',' << row[1] << ',' << row[2] << ',' << row[3]
              << ',' << row[4] << '\n';
      });
    }

    void
    write_free_end_summary(std::ostream &out, const FreeEnd &result)
    {
      const EndDecay &d = result.decay;
      const auto      b = cylindrical(result.bulge_at);
      out << "line_load_middle_N_per_mm = " << d.q_far << '\n'
          << "line_load_end_N_per_mm = " << d.q_end << '\n'
          << "line_load_mean_N_per_mm = " << d.q_mean << '\n'
          << "end_deficit_length_l_mm = " << d.deficit_length << '\n'
          << "end_rise_95_mm = " << d.rise_95 << '\n'
          << "end_rise_99_mm = " << d.rise_99 << '\n'
          << "end_bulge_uz_mm = " << result.bulge << '\n'
          << "end_bulge_r_mm = " << b[0] << '\n'
          << "end_bulge_theta_deg = " << b[1] << '\n'
          << "bond_shear_peak_MPa = " << result.shear_peak.shear() << '\n'
          << "bond_shear_middle_MPa = " << result.shear_middle.shear() << '\n'
          << "bond_corner_sigma_rr_mean_half_h_MPa = "
          << result.corner_sigma_rr[0] << '\n'
          << "bond_corner_sigma_rr_mean_h_MPa = " << result.corner_sigma_rr[1]
          << '\n'
          << "bond_corner_tau_rz_mean_half_h_MPa = " << result.corner_tau_rz[0]
          << '\n'
          << "bond_corner_tau_rz_mean_h_MPa = " << result.corner_tau_rz[1]
          << '\n';
      write_stress(out, "bond_shear_peak", result.shear_peak);
      write_stress(out, "bond_tension_peak", result.tension_peak);
      write_stress(out, "bond_tension_middle", result.tension_middle);
      write_stress(out, "bond_compression_peak", result.compression_peak);
      write_stress(out, "bond_compression_middle", result.compression_middle);
    }
  } // namespace three_d
} // namespace rollnip
