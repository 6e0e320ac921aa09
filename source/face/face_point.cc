#include <rollnip/face/face_point.h>

#include <cmath>

namespace rollnip
{
  namespace Face
  {
    double
    face_gauss_point(const unsigned int g)
    {
      static const double points[n_face_points] = {0.5 - std::sqrt(0.15),
                                                   0.5,
                                                   0.5 + std::sqrt(0.15)};
      return points[g];
    }

    double
    face_gauss_weight(const unsigned int g)
    {
      static const double weights[n_face_points] = {5. / 18, 8. / 18, 5. / 18};
      return weights[g];
    }

    FacePoint
    face_point(const FaceModel   &model,
               const FaceMesh    &mesh,
               const unsigned int e,
               const unsigned int g)
    {
      const double h  = mesh.y[e + 1] - mesh.y[e];
      const double xi = face_gauss_point(g);
      FacePoint    p;
      p.element = e;
      p.y       = mesh.y[e] + xi * h;
      p.weight  = face_gauss_weight(g) * h;
      p.crown   = model.crown ? model.crown(p.y) : 0.;
      p.roll    = deflection_shape(xi, h, shear_ratio(model.roll, h));
      p.mate    = deflection_shape(xi, h, shear_ratio(model.mate, h));
      return p;
    }

    double
    local_approach(const Eigen::VectorXd &x,
                   const FacePoint       &p,
                   const unsigned int     approach,
                   const unsigned int     n_roll,
                   const bool             with_mate)
    {
      double d = x[approach] + p.crown;
      for (unsigned int i = 0; i < 4; ++i)
        {
          d -= p.roll[i] * x[2 * p.element + i];
          if (with_mate)
            d -= p.mate[i] * x[n_roll + 2 * p.element + i];
        }
      return d;
    }

    void
    apply_supports(const std::vector<unsigned int>           &supports,
                   const std::vector<Eigen::Triplet<double>> &fixed,
                   std::vector<Eigen::Triplet<double>>        entries,
                   const unsigned int                         n,
                   Eigen::VectorXd                           &residual,
                   Eigen::SparseMatrix<double>               *tangent)
    {
      for (const unsigned int s : supports)
        residual[s] = 0;
      if (!tangent)
        return;
      std::vector<bool> supported(n, false);
      for (const unsigned int s : supports)
        supported[s] = true;
      entries.insert(entries.end(), fixed.begin(), fixed.end());
      std::vector<Eigen::Triplet<double>> kept;
      for (const auto &e : entries)
        if (!supported[e.row()] && !supported[e.col()])
          kept.push_back(e);
      for (const unsigned int s : supports)
        kept.emplace_back(s, s, 1.);
      tangent->resize(n, n);
      tangent->setFromTriplets(kept.begin(), kept.end());
    }
  } // namespace Face
} // namespace rollnip
