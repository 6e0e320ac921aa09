#include <deal.II/base/exceptions.h>

#include <rollnip/face/face_point.h>
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

      /// A quadrature point of the face: both beams' deflection shapes and
      /// the hat functions of the line load's two nodes.
      struct Point : FacePoint
      {
        unsigned int face_node; ///< left face node
        double       hat[2];
      };

      /**
       * The non-local face: x = (roll dofs, mate dofs, a, q at the face
       * nodes). Equations: the beams under the piecewise linear q, the
       * weak form of q - l^2 q'' = P(delta) with q = 0 at the face ends,
       * and int q = F in the row of a.
       */
      class NonlocalSystem
      {
      public:
        NonlocalSystem(const FaceModel &model, const FaceMesh &mesh);

        unsigned int       n_roll, n_mate, n_q, i_a, i_q, n;
        std::vector<Point> points;

        void
        assemble(const Eigen::VectorXd       &x,
                 Eigen::VectorXd             &r,
                 Eigen::SparseMatrix<double> *J) const;

        /// K u - f - C q at the bearings' w dofs.
        std::vector<double>
        support_forces(const Eigen::VectorXd &x) const;

        double
        delta(const Eigen::VectorXd &x, const Point &p) const;

      private:
        const FaceModel          &model;
        Triplets                  fixed; ///< K, -C, A and the force row
        Eigen::VectorXd           loads;
        std::vector<unsigned int> supports;
        double                    tangent_floor;
      };

      NonlocalSystem::NonlocalSystem(const FaceModel &model,
                                     const FaceMesh  &mesh)
          : model(model)
      {
        n_roll = 2 * mesh.n_nodes();
        n_mate = model.mate_is_beam ? 2 * mesh.n_nodes() : 0;
        n_q    = mesh.last_face_node - mesh.first_face_node + 1;
        i_a    = n_roll + n_mate;
        i_q    = i_a + 1;
        n      = i_q + n_q;
        loads  = Eigen::VectorXd::Zero(n);
        tangent_floor =
          1e-9 * model.roll.bending_stiffness / std::pow(model.face_length, 4);
        add_beam_matrix(
          mesh, model.roll, model.roll_beam_load, 0, fixed, loads);
        supports = {0, n_roll - 2};
        if (model.mate_is_beam)
          {
            add_beam_matrix(
              mesh, model.mate, model.mate_beam_load, n_roll, fixed, loads);
            supports.push_back(n_roll);
            supports.push_back(n_roll + n_mate - 2);
          }
        const double l2 = model.nonlocal_length * model.nonlocal_length;
        for (unsigned int e = mesh.first_face_node; e < mesh.last_face_node;
             ++e)
          {
            const double       h = mesh.y[e + 1] - mesh.y[e];
            const unsigned int k = e - mesh.first_face_node;
            // A = M + l^2 S of the linear elements.
            const double m[2][2] = {{h / 3, h / 6}, {h / 6, h / 3}};
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int j = 0; j < 2; ++j)
                fixed.emplace_back(i_q + k + i,
                                   i_q + k + j,
                                   m[i][j] + l2 / h * (i == j ? 1 : -1));
            for (unsigned int g = 0; g < n_face_points; ++g)
              {
                Point p;
                static_cast<FacePoint &>(p) = face_point(model, mesh, e, g);
                p.face_node                 = k;
                p.hat[0]                    = 1 - face_gauss_point(g);
                p.hat[1]                    = face_gauss_point(g);
                points.push_back(p);
                for (unsigned int j = 0; j < 2; ++j)
                  {
                    // The beams carry -int N q; the force row int q.
                    for (unsigned int i = 0; i < 4; ++i)
                      {
                        fixed.emplace_back(2 * e + i,
                                           i_q + k + j,
                                           -p.weight * p.roll[i] * p.hat[j]);
                        if (n_mate > 0)
                          fixed.emplace_back(n_roll + 2 * e + i,
                                             i_q + k + j,
                                             -p.weight * p.mate[i] * p.hat[j]);
                      }
                    fixed.emplace_back(i_a, i_q + k + j, p.weight * p.hat[j]);
                  }
              }
          }
        supports.push_back(i_q);
        supports.push_back(n - 1);
      }

      double
      NonlocalSystem::delta(const Eigen::VectorXd &x, const Point &p) const
      {
        return local_approach(x, p, i_a, n_roll, n_mate > 0);
      }

      void
      NonlocalSystem::assemble(const Eigen::VectorXd       &x,
                               Eigen::VectorXd             &r,
                               Eigen::SparseMatrix<double> *J) const
      {
        Eigen::SparseMatrix<double> F(n, n);
        F.setFromTriplets(fixed.begin(), fixed.end());
        r = F * x - loads;
        r[i_a] -= model.total_force;
        Triplets entries;
        for (const Point &p : points)
          {
            const double d = delta(x, p);
            const double P = model.law->load(d);
            const double t = std::max(model.law->tangent(d), tangent_floor);
            for (unsigned int j = 0; j < 2; ++j)
              {
                const unsigned int row = i_q + p.face_node + j;
                r[row] -= p.weight * P * p.hat[j];
                if (!J)
                  continue;
                entries.emplace_back(row, i_a, -p.weight * t * p.hat[j]);
                for (unsigned int i = 0; i < 4; ++i)
                  {
                    entries.emplace_back(row,
                                         2 * p.element + i,
                                         p.weight * t * p.hat[j] * p.roll[i]);
                    if (n_mate > 0)
                      entries.emplace_back(row,
                                           n_roll + 2 * p.element + i,
                                           p.weight * t * p.hat[j] * p.mate[i]);
                  }
              }
          }
        apply_supports(supports, fixed, std::move(entries), n, r, J);
      }

      std::vector<double>
      NonlocalSystem::support_forces(const Eigen::VectorXd &x) const
      {
        Eigen::SparseMatrix<double> F(n, n);
        F.setFromTriplets(fixed.begin(), fixed.end());
        const Eigen::VectorXd r = F * x - loads;
        std::vector<double>   f;
        for (unsigned int i = 0; i + 2 < supports.size(); ++i)
          f.push_back(r[supports[i]]);
        return f;
      }
    } // namespace

    void
    solve_nonlocal(const FaceModel &model, FaceSolution &solution)
    {
      NonlocalSystem  system(model, solution.mesh);
      Eigen::VectorXd x     = Eigen::VectorXd::Zero(system.n), r, dx;
      x.head(system.n_roll) = solution.roll;
      x.segment(system.n_roll, system.n_mate) = solution.mate;
      x[system.i_a]                           = solution.approach;
      const FaceMesh &mesh                    = solution.mesh;
      // The local load at the interior nodes is the start.
      for (unsigned int k = 1; k + 1 < system.n_q; ++k)
        x[system.i_q + k] = model.law->load(
          solution.approach_at(mesh.y[mesh.first_face_node + k]));
      Eigen::SparseMatrix<double> J;
      const double                tolerance = 1e-10 * model.total_force;
      bool                        converged = false;
      for (unsigned int it = 0; it < 100 && !converged; ++it)
        {
          system.assemble(x, r, &J);
          const double norm = r.norm();
          if (r.lpNorm<Eigen::Infinity>() <= tolerance)
            {
              converged = true;
              break;
            }
          Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(J);
          AssertThrow(lu.info() == Eigen::Success,
                      ExcMessage("face: the non-local tangent is singular"));
          dx = -lu.solve(r);
          // Backtracking on the residual's norm.
          double          step = 1;
          Eigen::VectorXd trial, r_trial;
          for (unsigned int k = 0; k < 30; ++k, step /= 2)
            {
              trial = x + step * dx;
              system.assemble(trial, r_trial, nullptr);
              if (r_trial.norm() <= (1 - 1e-4 * step) * norm)
                break;
            }
          x = trial;
          ++solution.iterations;
          converged = step * dx.lpNorm<Eigen::Infinity>() <=
                      1e-14 * x.lpNorm<Eigen::Infinity>();
        }
      AssertThrow(converged,
                  ExcMessage("face: the non-local Newton did not converge "
                             "in 100 iterations"));
      solution.roll               = x.head(system.n_roll);
      solution.mate               = x.segment(system.n_roll, system.n_mate);
      solution.approach           = x[system.i_a];
      solution.nodal_line_load    = x.tail(system.n_q);
      const std::vector<double> f = system.support_forces(x);
      solution.roll_bearings      = {{-f[0], -f[1]}};
      if (model.mate_is_beam)
        solution.mate_bearings = {{-f[2], -f[3]}};
    }
  } // namespace Face
} // namespace rollnip
