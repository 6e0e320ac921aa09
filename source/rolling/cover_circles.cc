#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <rollnip/fe_fields.h>
#include <rollnip/rolling/cover_circles.h>

#include <algorithm>
#include <cmath>

namespace rollnip
{
  RingCell
  ring_cell(const Triangulation<dim>::cell_iterator &cell)
  {
    std::array<double, 4> r;
    for (unsigned int v = 0; v < 4; ++v)
      r[v] = cell->vertex(v).norm();
    RingCell     ring;
    const double tolerance = 1e-9 * std::max(r[0], r[3]);
    // deal.II's vertices 0, 1 lie on unit y = 0, vertices 0, 2 on x = 0.
    ring.xi_circumferential  = std::abs(r[1] - r[0]) <= tolerance;
    const unsigned int other = ring.xi_circumferential ? 2 : 1;
    const unsigned int last  = ring.xi_circumferential ? 1 : 2;
    ring.inner_radius        = std::min(r[0], r[other]);
    ring.outer_radius        = std::max(r[0], r[other]);
    AssertThrow(std::abs(r[3] - r[other]) <= tolerance &&
                  std::abs(r[last] - r[0]) <= tolerance &&
                  ring.outer_radius - ring.inner_radius > tolerance,
                ExcMessage("Rolling: a cell at (" +
                           std::to_string(cell->center()[0]) + ", " +
                           std::to_string(cell->center()[1]) +
                           ") mm does not lie between two circles about the "
                           "roll axis: the loss needs a mesh of rings"));
    return ring;
  }

  CircleQuadrature
  circle_quadrature(const unsigned int degree)
  {
    const QGauss<1>     across(degree + 1);
    const Quadrature<1> along =
      degree == 1 ? Quadrature<1>(Point<1>(0.5)) : Quadrature<1>(QGauss<1>(2));
    CircleQuadrature        q;
    std::vector<Point<dim>> xi_along, eta_along;
    for (unsigned int j = 0; j < across.size(); ++j)
      for (unsigned int i = 0; i < along.size(); ++i)
        {
          xi_along.emplace_back(along.point(i)[0], across.point(j)[0]);
          eta_along.emplace_back(across.point(j)[0], along.point(i)[0]);
          q.radial_coordinate.push_back(across.point(j)[0]);
          q.radial_weight.push_back(across.weight(j));
        }
    q.points[0] = Quadrature<dim>(xi_along);
    q.points[1] = Quadrature<dim>(eta_along);
    return q;
  }

  Tensor<2, dim>
  isochoric_stress(const Tensor<2, dim> &grad_u,
                   const double          C1,
                   const double          C2,
                   const bool            linear)
  {
    const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
    if (linear)
      {
        const Tensor<2, dim> eps = 0.5 * (grad_u + transpose(grad_u));
        // dev of the 3x3 strain with eps_zz = 0, in-plane part.
        return 4. * (C1 + C2) * (eps - trace(eps) / 3. * I);
      }
    const Tensor<2, dim> F     = I + grad_u;
    const Tensor<2, dim> C     = transpose(F) * F;
    const double         J     = determinant(F);
    const double         Jm    = std::pow(J, -2. / 3.);
    const double         I1bar = Jm * (trace(C) + 1.);
    // Sbar = 2 C1 I + 2 C2 (I1bar I - Cbar), in-plane and zz parts.
    const Tensor<2, dim> Sbar  = 2. * C1 * I + 2. * C2 * (I1bar * I - Jm * C);
    const double         Sbar3 = 2. * C1 + 2. * C2 * (I1bar - Jm);
    const double         SC    = scalar_product(Sbar, C) + Sbar3;
    return Jm * (Sbar - SC / 3. * invert(C));
  }

  namespace
  {
    /// Polar components (rr, rtheta, thetatheta) of @p T at angle @p phi.
    std::array<double, 3>
    polar(const Tensor<2, dim> &T, const double phi)
    {
      const double c = std::cos(phi), s = std::sin(phi);
      const double rr =
        c * c * T[0][0] + c * s * (T[0][1] + T[1][0]) + s * s * T[1][1];
      const double tt =
        s * s * T[0][0] - c * s * (T[0][1] + T[1][0]) + c * c * T[1][1];
      const double rt =
        -c * s * T[0][0] + c * c * T[0][1] - s * s * T[1][0] + c * s * T[1][1];
      return {{rr, rt, tt}};
    }

    /// Size of one gathered sample: radius, weight, layer, theta, E, S.
    constexpr unsigned int record = 10;

    /// The samples of the owned cells, flattened.
    std::vector<double>
    local_samples(const RollBody &body)
    {
      const unsigned int     degree = body.fe().degree;
      const CircleQuadrature cq     = circle_quadrature(degree);
      std::array<std::unique_ptr<FEValues<dim>>, 2> fe_values;
      for (unsigned int k = 0; k < 2; ++k)
        fe_values[k] =
          std::make_unique<FEValues<dim>>(body.mapping(),
                                          body.fe(),
                                          cq.points[k],
                                          update_gradients |
                                            update_quadrature_points);
      const auto                 &material = body.scene().material;
      const bool                  linear   = body.materials().is_linear();
      std::vector<Tensor<2, dim>> grad_u(cq.radial_weight.size());
      std::vector<double>         flat;
      for (const auto &cell : body.dofs().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const RingCell ring = ring_cell(cell);
            auto          &fv   = *fe_values[ring.xi_circumferential ? 0 : 1];
            fv.reinit(cell);
            fv[FEFields::displacement].get_function_gradients(body.solution(),
                                                              grad_u);
            const unsigned int layer =
              material.n_layers() == 1 ? 0 : cell->material_id();
            const double C1 = material.layer_C1[layer];
            const double C2 = material.layer_C2[layer];
            const double dr = ring.outer_radius - ring.inner_radius;
            // Which way the radial unit coordinate runs in this cell.
            const unsigned int across = ring.xi_circumferential ? 1 : 0;
            const bool         outward =
              cell->vertex(across == 1 ? 2 : 1).norm() > cell->vertex(0).norm();
            for (unsigned int q = 0; q < grad_u.size(); ++q)
              {
                const double s = cq.radial_coordinate[q];
                const double r = ring.inner_radius + (outward ? s : 1 - s) * dr;
                const Point<dim>    &X     = fv.quadrature_point(q);
                const double         theta = std::atan2(X[1], X[0]);
                const Tensor<2, dim> gu    = grad_u[q];
                const Tensor<2, dim> E =
                  linear ? Tensor<2, dim>(0.5 * (gu + transpose(gu)))
                         : Tensor<2, dim>(
                             0.5 * (transpose(gu) + gu + transpose(gu) * gu));
                const auto Ep = polar(E, theta);
                const auto Sp =
                  polar(isochoric_stress(gu, C1, C2, linear), theta);
                flat.insert(flat.end(),
                            {r,
                             cq.radial_weight[q] * dr * r,
                             double(layer),
                             theta,
                             Ep[0],
                             Ep[1],
                             Ep[2],
                             Sp[0],
                             Sp[1],
                             Sp[2]});
              }
          }
      return flat;
    }
  } // namespace

  std::vector<MaterialCircle>
  cover_circles(const RollBody &body)
  {
    std::vector<std::array<double, record>> all;
    for (const auto &part :
         Utilities::MPI::all_gather(body.communicator(), local_samples(body)))
      for (std::size_t i = 0; i + record <= part.size(); i += record)
        {
          std::array<double, record> a;
          std::copy(part.begin() + i, part.begin() + i + record, a.begin());
          all.push_back(a);
        }
    std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) {
      return a[0] < b[0] || (a[0] == b[0] && a[3] < b[3]);
    });
    std::vector<MaterialCircle> circles;
    const double tolerance = 1e-9 * body.scene().geometry.outer_radius;
    for (const auto &a : all)
      {
        if (circles.empty() || a[0] - circles.back().radius > tolerance)
          circles.push_back({a[0], a[1], static_cast<unsigned int>(a[2]), {}});
        circles.back().samples.push_back(
          {a[3], {{a[4], a[5], a[6]}}, {{a[7], a[8], a[9]}}});
      }
    // Within a circle the samples came sorted by radius first: by angle.
    for (auto &c : circles)
      std::sort(c.samples.begin(),
                c.samples.end(),
                [](const CircleSample &a, const CircleSample &b) {
                  return a.theta < b.theta;
                });
    return circles;
  }
} // namespace rollnip
