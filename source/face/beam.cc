#include <deal.II/base/numbers.h>

#include <rollnip/face/beam.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>

namespace rollnip
{
  namespace Face
  {
    BeamSection
    tube_section(const Parameters::FaceCore &core, const bool shear)
    {
      const double pi = numbers::PI;
      const double Do = core.outer_diameter, Di = core.inner_diameter;
      const double A = pi / 4 * (Do * Do - Di * Di);
      BeamSection  s;
      s.bending_stiffness =
        core.youngs_modulus * pi / 64 * (std::pow(Do, 4) - std::pow(Di, 4));
      if (shear)
        {
          // Cowper (1966), the shear coefficient of a thick-walled tube.
          const double nu = core.poisson_ratio;
          const double m  = Di / Do;
          const double c  = (1 + m * m) * (1 + m * m);
          const double kappa =
            6 * (1 + nu) * c / ((7 + 6 * nu) * c + (20 + 12 * nu) * m * m);
          s.shear_stiffness = kappa * core.youngs_modulus / (2 * (1 + nu)) * A;
        }
      // kg/m^3 * mm^2 * 9.81 m/s^2 = 9.81e-9 N/mm.
      s.weight = core.density * A * 9.81e-9;
      return s;
    }

    FaceMesh::FaceMesh(const double       face_length,
                       const double       bearing_distance,
                       const unsigned int face_elements)
    {
      const double h       = face_length / face_elements;
      const double journal = (bearing_distance - face_length) / 2;
      // Journals shorter than a thousandth of an element are none.
      const unsigned int n_journal =
        journal > 1e-3 * h ? static_cast<unsigned int>(std::ceil(journal / h))
                           : 0;
      for (unsigned int i = 0; i < n_journal; ++i)
        y.push_back(-bearing_distance / 2 + i * journal / n_journal);
      first_face_node = y.size();
      for (unsigned int i = 0; i <= face_elements; ++i)
        y.push_back(-face_length / 2 + i * h);
      y.back()       = face_length / 2;
      last_face_node = y.size() - 1;
      for (unsigned int i = 1; i <= n_journal; ++i)
        y.push_back(face_length / 2 + i * journal / n_journal);
      if (n_journal > 0)
        y.back() = bearing_distance / 2;
    }

    unsigned int
    FaceMesh::element_at(const double y0) const
    {
      const auto it = std::upper_bound(y.begin(), y.end(), y0);
      const int  e  = static_cast<int>(it - y.begin()) - 1;
      return std::clamp(e, 0, static_cast<int>(y.size()) - 2);
    }

    double
    shear_ratio(const BeamSection &section, const double h)
    {
      if (section.shear_stiffness <= 0)
        return 0;
      return 12 * section.bending_stiffness / (section.shear_stiffness * h * h);
    }

    Eigen::Matrix4d
    element_stiffness(const BeamSection &section, const double h)
    {
      const double    phi = shear_ratio(section, h);
      const double    c   = section.bending_stiffness / ((1 + phi) * h * h * h);
      Eigen::Matrix4d k;
      // clang-format off
      k << 12,     6 * h,                 -12,    6 * h,
           6 * h,  (4 + phi) * h * h,     -6 * h, (2 - phi) * h * h,
           -12,    -6 * h,                12,     -6 * h,
           6 * h,  (2 - phi) * h * h,     -6 * h, (4 + phi) * h * h;
      // clang-format on
      return c * k;
    }

    std::array<double, 4>
    deflection_shape(const double xi, const double h, const double phi)
    {
      // Friedman and Kosmatka (1993): the deflection of the element that
      // solves the homogeneous Timoshenko equations exactly.
      const double mu = 1 / (1 + phi);
      const double x2 = xi * xi, x3 = x2 * xi;
      return {{mu * (2 * x3 - 3 * x2 - phi * xi + 1 + phi),
               h * mu * (x3 - (2 + phi / 2) * x2 + (1 + phi / 2) * xi),
               mu * (-2 * x3 + 3 * x2 + phi * xi),
               h * mu * (x3 - (1 - phi / 2) * x2 - phi / 2 * xi)}};
    }

    double
    deflection_at(const FaceMesh        &mesh,
                  const BeamSection     &section,
                  const Eigen::VectorXd &u,
                  const double           y0)
    {
      const unsigned int e  = mesh.element_at(y0);
      const double       h  = mesh.y[e + 1] - mesh.y[e];
      const double       xi = (y0 - mesh.y[e]) / h;
      const auto         N  = deflection_shape(xi, h, shear_ratio(section, h));
      double             w  = 0;
      for (unsigned int i = 0; i < 4; ++i)
        w += N[i] * u[2 * e + i];
      return w;
    }

    void
    add_beam_matrix(const FaceMesh                      &mesh,
                    const BeamSection                   &section,
                    const double                         load,
                    const unsigned int                   offset,
                    std::vector<Eigen::Triplet<double>> &entries,
                    Eigen::VectorXd                     &forces)
    {
      for (unsigned int e = 0; e + 1 < mesh.n_nodes(); ++e)
        {
          const double          h = mesh.y[e + 1] - mesh.y[e];
          const Eigen::Matrix4d k = element_stiffness(section, h);
          // The fixed-end forces of a uniform load, shear or not.
          const std::array<double, 4> f = {{load * h / 2,
                                            load * h * h / 12,
                                            load * h / 2,
                                            -load * h * h / 12}};
          for (unsigned int i = 0; i < 4; ++i)
            {
              forces[offset + 2 * e + i] += f[i];
              for (unsigned int j = 0; j < 4; ++j)
                entries.emplace_back(offset + 2 * e + i,
                                     offset + 2 * e + j,
                                     k(i, j));
            }
        }
    }

    Eigen::VectorXd
    simply_supported_deflection(const FaceMesh    &mesh,
                                const BeamSection &section,
                                const double       face_load,
                                const double       beam_load)
    {
      const unsigned int                  n = 2 * mesh.n_nodes();
      std::vector<Eigen::Triplet<double>> entries;
      Eigen::VectorXd                     f = Eigen::VectorXd::Zero(n);
      for (unsigned int e = 0; e + 1 < mesh.n_nodes(); ++e)
        {
          const double h = mesh.y[e + 1] - mesh.y[e];
          const double q = beam_load + (mesh.on_face(e) ? face_load : 0.);
          const Eigen::Matrix4d k = element_stiffness(section, h);
          // The fixed-end forces of a uniform load, shear or not.
          const std::array<double, 4> fe = {
            {q * h / 2, q * h * h / 12, q * h / 2, -q * h * h / 12}};
          for (unsigned int i = 0; i < 4; ++i)
            {
              f[2 * e + i] += fe[i];
              for (unsigned int j = 0; j < 4; ++j)
                entries.emplace_back(2 * e + i, 2 * e + j, k(i, j));
            }
        }
      // The supports: w = 0 at the bearings, by a unit row and column.
      const unsigned int                  supported[2] = {0, n - 2};
      std::vector<Eigen::Triplet<double>> kept;
      for (const auto &t : entries)
        if (std::find(std::begin(supported), std::end(supported), t.row()) ==
              std::end(supported) &&
            std::find(std::begin(supported), std::end(supported), t.col()) ==
              std::end(supported))
          kept.push_back(t);
      for (const unsigned int s : supported)
        {
          kept.emplace_back(s, s, 1.);
          f[s] = 0;
        }
      Eigen::SparseMatrix<double> K(n, n);
      K.setFromTriplets(kept.begin(), kept.end());
      Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(K);
      return lu.solve(f);
    }
  } // namespace Face
} // namespace rollnip
