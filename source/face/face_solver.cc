#include <deal.II/base/exceptions.h>

#include <rollnip/face/face_point.h>
#include <rollnip/face/face_solver.h>
#include <rollnip/face/nonlocal_face.h>
#include <rollnip/global.h>

#include <Eigen/Sparse>

#include <cmath>
#include <utility>
#include <vector>

namespace rollnip
{
  namespace Face
  {
    namespace
    {
      using Triplets = std::vector<Eigen::Triplet<double>>;


      /// The discrete face problem: x = (roll dofs, mate dofs, a).
      class FaceSystem
      {
      public:
        FaceSystem(const FaceModel &model, const FaceMesh &mesh);

        unsigned int n_roll, n_mate, n;

        /// The residual at @p x and, if asked, the tangent; rows and
        /// columns of the supports are unit ones with zero residual.
        void
        assemble(const Eigen::VectorXd       &x,
                 Eigen::VectorXd             &residual,
                 Eigen::SparseMatrix<double> *tangent) const;

        /// The support forces on the beams (K u - f - int N q at the
        /// bearings' w dofs): roll left, right, mate left, right.
        std::array<double, 4>
        support_forces(const Eigen::VectorXd &x) const;

        /// The round-off scale of the residual at @p x: the largest sum of
        /// |K_ij x_j| over a row.
        double
        force_scale(const Eigen::VectorXd &x) const;

        /// The uniform approach that carries the total force with both
        /// beams straight: the start of Newton.
        double
        straight_approach() const;

        std::vector<FacePoint> points;

      private:
        const FaceModel          &model;
        const FaceMesh           &mesh;
        Triplets                  beam_entries;
        Eigen::VectorXd           beam_loads;
        std::vector<unsigned int> supports;
        /// A floor of the foundation's tangent, 1e-9 EI / L^4, keeps the
        /// tangent regular where the nip is open (it moves the Newton
        /// path, not the solution).
        double tangent_floor;

        double
        delta(const Eigen::VectorXd &x, const FacePoint &p) const;
        void
        add_beam(const BeamSection &section,
                 const double       load,
                 const unsigned int offset);
      };

      FaceSystem::FaceSystem(const FaceModel &model, const FaceMesh &mesh)
          : model(model)
          , mesh(mesh)
      {
        n_roll     = 2 * mesh.n_nodes();
        n_mate     = model.mate_is_beam ? 2 * mesh.n_nodes() : 0;
        n          = n_roll + n_mate + 1;
        beam_loads = Eigen::VectorXd::Zero(n);
        tangent_floor =
          1e-9 * model.roll.bending_stiffness / std::pow(model.face_length, 4);
        add_beam(model.roll, model.roll_beam_load, 0);
        if (model.mate_is_beam)
          add_beam(model.mate, model.mate_beam_load, n_roll);
        for (unsigned int e = mesh.first_face_node; e < mesh.last_face_node;
             ++e)
          {
            for (unsigned int g = 0; g < n_face_points; ++g)
              points.push_back(face_point(model, mesh, e, g));
          }
      }

      void
      FaceSystem::add_beam(const BeamSection &section,
                           const double       load,
                           const unsigned int offset)
      {
        add_beam_matrix(mesh, section, load, offset, beam_entries, beam_loads);
        supports.push_back(offset);
        supports.push_back(offset + 2 * (mesh.n_nodes() - 1));
      }

      double
      FaceSystem::delta(const Eigen::VectorXd &x, const FacePoint &p) const
      {
        return local_approach(x, p, n - 1, n_roll, n_mate > 0);
      }

      void
      FaceSystem::assemble(const Eigen::VectorXd       &x,
                           Eigen::VectorXd             &residual,
                           Eigen::SparseMatrix<double> *tangent) const
      {
        Eigen::SparseMatrix<double> K(n, n);
        K.setFromTriplets(beam_entries.begin(), beam_entries.end());
        residual        = K * x - beam_loads;
        residual[n - 1] = -model.total_force;
        Triplets entries;
        for (const FacePoint &p : points)
          {
            const double d = delta(x, p);
            const double q = model.law->load(d);
            const double t = std::max(model.law->tangent(d), tangent_floor);
            // Dofs of the point and the sign of delta on each: -1 on the
            // beams' deflections, +1 on the approach.
            std::array<unsigned int, 9> dof;
            std::array<double, 9>       dd;
            unsigned int                m = 0;
            for (unsigned int i = 0; i < 4; ++i, ++m)
              dof[m] = 2 * p.element + i, dd[m] = -p.roll[i];
            if (n_mate > 0)
              for (unsigned int i = 0; i < 4; ++i, ++m)
                dof[m] = n_roll + 2 * p.element + i, dd[m] = -p.mate[i];
            dof[m] = n - 1, dd[m] = 1, ++m;
            // R_i = ... + w q dd_i reproduces -int N q on the beams and
            // +int q on the force equation.
            for (unsigned int i = 0; i < m; ++i)
              {
                residual[dof[i]] += p.weight * q * dd[i];
                if (tangent)
                  for (unsigned int j = 0; j < m; ++j)
                    entries.emplace_back(dof[i],
                                         dof[j],
                                         p.weight * t * dd[i] * dd[j]);
              }
          }
        apply_supports(
          supports, beam_entries, std::move(entries), n, residual, tangent);
      }

      std::array<double, 4>
      FaceSystem::support_forces(const Eigen::VectorXd &x) const
      {
        Eigen::SparseMatrix<double> K(n, n);
        K.setFromTriplets(beam_entries.begin(), beam_entries.end());
        Eigen::VectorXd r = K * x - beam_loads;
        for (const FacePoint &p : points)
          {
            const double q = model.law->load(delta(x, p));
            for (unsigned int i = 0; i < 4; ++i)
              {
                r[2 * p.element + i] -= p.weight * q * p.roll[i];
                if (n_mate > 0)
                  r[n_roll + 2 * p.element + i] -= p.weight * q * p.mate[i];
              }
          }
        std::array<double, 4> f{{0, 0, 0, 0}};
        for (unsigned int i = 0; i < supports.size(); ++i)
          f[i] = r[supports[i]];
        return f;
      }

      double
      FaceSystem::force_scale(const Eigen::VectorXd &x) const
      {
        Eigen::SparseMatrix<double> K(n, n);
        K.setFromTriplets(beam_entries.begin(), beam_entries.end());
        return (K.cwiseAbs() * x.cwiseAbs()).lpNorm<Eigen::Infinity>();
      }

      double
      FaceSystem::straight_approach() const
      {
        auto force = [&](const double a) {
          double f = 0;
          for (const FacePoint &p : points)
            f += p.weight * model.law->load(a + p.crown);
          return f;
        };
        double lo = 0, hi = 1e-3;
        for (const FacePoint &p : points)
          lo = std::min(lo, -p.crown);
        for (unsigned int i = 0; force(hi) < model.total_force; ++i)
          {
            AssertThrow(i < 200,
                        ExcMessage("face: no approach carries the total "
                                   "force"));
            lo = hi;
            hi *= 2;
          }
        for (unsigned int i = 0; i < 200 && hi - lo > 1e-14 * hi; ++i)
          {
            const double mid                           = (lo + hi) / 2;
            (force(mid) < model.total_force ? lo : hi) = mid;
          }
        return (lo + hi) / 2;
      }

      /// The step length along @p dx from @p x: the root of the energy's
      /// slope g(s) = dx . R(x + s dx), which grows with s (the energy is
      /// convex), by regula falsi; 1 when the full step is good enough.
      double
      step_length(const FaceSystem      &system,
                  const Eigen::VectorXd &x,
                  const Eigen::VectorXd &dx,
                  const double           g0)
      {
        Eigen::VectorXd r;
        auto            slope = [&](const double s) {
          system.assemble(x + s * dx, r, nullptr);
          return dx.dot(r);
        };
        double g1 = slope(1.);
        if (g1 <= 0.5 * std::abs(g0))
          return 1.;
        double lo = 0, glo = g0, hi = 1, ghi = g1, s = 1;
        for (unsigned int i = 0; i < 30; ++i)
          {
            s              = (lo * ghi - hi * glo) / (ghi - glo);
            const double g = slope(s);
            if (std::abs(g) <= 0.5 * std::abs(g0))
              break;
            if (g < 0)
              lo = s, glo = g, ghi /= 2;
            else
              hi = s, ghi = g, glo /= 2;
          }
        return s;
      }
    } // namespace

    FaceSolution::FaceSolution(const FaceModel &model)
        : model(&model)
        , mesh(model.face_length, model.bearing_distance, model.elements)
    {}

    double
    FaceSolution::roll_deflection(const double y) const
    {
      return deflection_at(mesh, model->roll, roll, y);
    }

    double
    FaceSolution::mate_deflection(const double y) const
    {
      return model->mate_is_beam ? deflection_at(mesh, model->mate, mate, y)
                                 : 0.;
    }

    double
    FaceSolution::crown(const double y) const
    {
      return model->crown ? model->crown(y) : 0.;
    }

    double
    FaceSolution::approach_at(const double y) const
    {
      return approach - roll_deflection(y) - mate_deflection(y) + crown(y);
    }

    double
    FaceSolution::line_load(const double y) const
    {
      if (nodal_line_load.size() == 0)
        return model->law->load(approach_at(y));
      // The non-local q: linear between the face nodes, 0 off the face.
      const double L = model->face_length;
      if (y < -L / 2 || y > L / 2)
        return 0;
      const unsigned int e =
        std::min(mesh.element_at(y), mesh.last_face_node - 1);
      const unsigned int k  = e - mesh.first_face_node;
      const double       xi = (y - mesh.y[e]) / (mesh.y[e + 1] - mesh.y[e]);
      return (1 - xi) * nodal_line_load[k] + xi * nodal_line_load[k + 1];
    }

    FaceSolution
    solve_face(const FaceModel &model)
    {
      AssertThrow(model.law, ExcMessage("face: no foundation law"));
      FaceSolution    solution(model);
      FaceSystem      system(model, solution.mesh);
      Eigen::VectorXd x = Eigen::VectorXd::Zero(system.n), r, dx;
      x[system.n - 1]   = system.straight_approach();
      Eigen::SparseMatrix<double> J;
      // Converged when the forces balance to 1e-10 of the nip force (or
      // to round-off of the beams' internal forces), or when a step moves
      // the state by round-off only.
      bool converged = false;
      for (unsigned int it = 0; it < 100 && !converged; ++it)
        {
          system.assemble(x, r, &J);
          solution.iterations = it;
          const double tolerance =
            1e-10 * model.total_force + 1e-13 * system.force_scale(x);
          if (r.lpNorm<Eigen::Infinity>() <= tolerance)
            {
              converged = true;
              break;
            }
          Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(J);
          AssertThrow(lu.info() == Eigen::Success,
                      ExcMessage("face: the tangent is singular"));
          dx                = -lu.solve(r);
          const double step = step_length(system, x, dx, dx.dot(r));
          x += step * dx;
          converged = step * dx.lpNorm<Eigen::Infinity>() <=
                      1e-14 * x.lpNorm<Eigen::Infinity>();
        }
      AssertThrow(converged,
                  ExcMessage("face: Newton did not converge in 100 "
                             "iterations (residual " +
                             std::to_string(r.lpNorm<Eigen::Infinity>()) +
                             " N)"));
      solution.roll          = x.head(system.n_roll);
      solution.mate          = x.segment(system.n_roll, system.n_mate);
      solution.approach      = x[system.n - 1];
      const auto f           = system.support_forces(x);
      solution.roll_bearings = {{-f[0], -f[1]}};
      solution.mate_bearings = {{-f[2], -f[3]}};
      if (model.nonlocal_length > 0)
        solve_nonlocal(model, solution);
      if (!model.mate_is_beam)
        {
          // A rigid mating roll: its bearings share the nip force by
          // statics.
          double force = 0, moment = 0;
          for (const FacePoint &p : system.points)
            {
              const double q = solution.line_load(p.y);
              force += p.weight * q;
              moment += p.weight * q * p.y;
            }
          solution.mate_bearings = {
            {force / 2 - moment / model.bearing_distance,
             force / 2 + moment / model.bearing_distance}};
        }
      return solution;
    }
  } // namespace Face
} // namespace rollnip
