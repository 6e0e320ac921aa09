#include <deal.II/base/mpi.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <rollnip/boundary_ids.h>
#include <rollnip/geometry/cover_layers.h>
#include <rollnip/geometry/nip_fitted_mesh.h>
#include <rollnip/geometry/roll_mesh.h>

#include <algorithm>
#include <cmath>

namespace rollnip
{
  namespace
  {
    /// The largest thickness over width of a coarse cell under a nip of the
    /// cover's size before the radial cells thin towards the surface
    /// (measured on the run-30 scene, a/h = 0.3-1.1, against Q2-P1: 3 or 4
    /// lose nothing against no thinning, thinning to 1 loses a factor 2-4
    /// in P per DoF).
    constexpr double max_nip_cell_aspect = 4;

    /// The half-width over cover thickness a/h at which a nip counts half
    /// as small against the cover and half as of the cover's size
    /// (NipFittedMesh::cover_weight).
    constexpr double thin_cover_nip = 0.2;

    /// sum_{k < n} g^k.
    double
    geometric_sum(const double g, const unsigned int n)
    {
      double s = 0, t = 1;
      for (unsigned int k = 0; k < n; ++k, t *= g)
        s += t;
      return s;
    }

    /// The growth factor g with first * sum_{k < n} g^k = length, by
    /// bisection to round-off, so that it is a smooth function of its
    /// arguments (the nip characteristic inherits its smoothness).
    double
    growth_factor(const double first, const unsigned int n, const double length)
    {
      double lo = 1e-3, hi = 1e3;
      for (unsigned int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i)
        {
          const double mid                                   = 0.5 * (lo + hi);
          (first * geometric_sum(mid, n) < length ? lo : hi) = mid;
        }
      return 0.5 * (lo + hi);
    }
  } // namespace

  MeshQuality
  mesh_quality(const parallel::distributed::Triangulation<dim> &triangulation)
  {
    MeshQuality q;
    // Corners of a quadrilateral in deal.II order, counter-clockwise.
    const unsigned int ccw[4] = {0, 1, 3, 2};
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          double det_min = std::numeric_limits<double>::max(), det_max = 0;
          for (unsigned int k = 0; k < 4; ++k)
            {
              const Point<dim>    &x    = cell->vertex(ccw[k]);
              const Point<dim>    &next = cell->vertex(ccw[(k + 1) % 4]);
              const Point<dim>    &prev = cell->vertex(ccw[(k + 3) % 4]);
              const Tensor<1, dim> a = next - x, b = prev - x;
              const double         det = a[0] * b[1] - a[1] * b[0];
              det_min                  = std::min(det_min, det);
              det_max                  = std::max(det_max, det);
            }
          q.min_jacobian_ratio = std::min(q.min_jacobian_ratio,
                                          det_max > 0 ? det_min / det_max : 0.);
        }
    q.min_jacobian_ratio =
      Utilities::MPI::min(q.min_jacobian_ratio,
                          triangulation.get_communicator());
    q.max_aspect_ratio =
      GridTools::compute_maximum_aspect_ratio(MappingQ1<dim>(),
                                              triangulation,
                                              QGauss<dim>(2));
    return q;
  }

  NipFittedMesh::NipFittedMesh(const Parameters::AllParameters &parameters)
      : sector_angle(parameters.geometry.sector_angle)
      , n_cells(parameters.mesh.circumferential_cells)
      , n_nip_cells(parameters.mesh.nip_cells)
      , nip_grading(parameters.mesh.nip_grading)
      , parameters(parameters)
  {
    Assert(n_nip_cells + 2 <= n_cells, ExcInternalError());
  }

  std::vector<double>
  NipFittedMesh::coarse_angles(const double theta0) const
  {
    std::vector<double> T(n_cells + 1, 0.);
    // Edge-graded for a nip small against the cover (Hertz-like: the
    // pressure's square-root edge is what the cells must resolve), relaxing
    // to uniform as the nip reaches the cover's size (measured against
    // Q2-P1, doc/accuracy.md).
    const double ratio = 1 + (nip_grading - 1) * (1 - cover_weight(theta0));
    const std::vector<double> nip =
      graded_steps(n_nip_cells, theta0, 1. / ratio);
    for (unsigned int k = 0; k < n_nip_cells; ++k)
      T[k + 1] = T[k] + nip[k];
    T[n_nip_cells]           = theta0; // exactly: it is the contact edge
    const unsigned int n_far = n_cells - n_nip_cells;
    // Cells beyond the nip start at the edge cell's width and grow (or,
    // on a short sector with many cells, shrink) geometrically to fill the
    // rest of the sector: no jump in width anywhere.
    const double g = growth_factor(nip.back(), n_far, sector_angle - theta0);
    double       w = nip.back();
    for (unsigned int k = n_nip_cells; k < n_cells; ++k, w *= g)
      T[k + 1] = T[k] + w;
    T[n_cells] = sector_angle;
    return T;
  }

  double
  NipFittedMesh::cover_weight(const double theta0) const
  {
    const auto  &g = parameters.geometry;
    const double x = g.outer_radius * std::sin(theta0) /
                     (thin_cover_nip * (g.outer_radius - g.inner_radius));
    // Steep, so that a nip small against the cover keeps the edge-graded
    // layout (a/h = 0.04: weight 1e-3; the thick two-roll nips of
    // contact_two_rolls fail their first pass already at 0.007).
    const double x4 = x * x * x * x;
    return x4 / (1 + x4);
  }

  std::vector<double>
  NipFittedMesh::coarse_radii(const double theta0) const
  {
    const auto        &g = parameters.geometry;
    const auto        &m = parameters.mesh;
    const unsigned int n = radial_steps(parameters, 1.).size();
    // The surface cell of the user's grading, thinned where a coarse nip
    // cell would be more than an aspect ratio times as thick as it is
    // wide: 1 for a nip small against the cover (it loads a surface layer
    // of depth ~a, which the cells must resolve), max_nip_cell_aspect for
    // a nip of the cover's size (it loads the whole thickness, and thinning
    // the surface would coarsen the cells that carry it to the core). A
    // smooth minimum, bounded below by a tenth of the user's cell, keeps
    // P(theta0) smooth.
    const double h      = g.outer_radius - g.inner_radius;
    const double w_user = graded_steps(n, h, m.radial_grading).back();
    const double aspect = 1 + (max_nip_cell_aspect - 1) * cover_weight(theta0);
    const double w_aspect = aspect * g.outer_radius * theta0 / n_nip_cells;
    const double w_low    = 0.1 * w_user;
    const double w_surface =
      1. / std::sqrt(1. / (w_user * w_user) +
                     1. / (w_aspect * w_aspect + w_low * w_low));
    // The total grading ratio whose last cell is w_surface, by bisection
    // (the last cell shrinks with the ratio). Both are the whole cover's
    // grading, which a layered cover follows layer by layer: a top layer
    // of one coarse cell cannot thin, and searching on its own cell drove
    // the ratio to its bound and the cells below the interface to aspect
    // ratios of 3e3.
    double lo = 1e-4, hi = std::max(1., m.radial_grading);
    for (unsigned int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i)
      {
        const double mid = 0.5 * (lo + hi);
        (graded_steps(n, h, mid).back() < w_surface ? lo : hi) = mid;
      }
    std::vector<double> radii(n + 1, g.inner_radius);
    const auto          steps = radial_steps(parameters, 0.5 * (lo + hi));
    for (unsigned int k = 0; k < n; ++k)
      radii[k + 1] = radii[k] + steps[k];
    radii[n] = g.outer_radius; // exactly: the surface
    return radii;
  }

  double
  NipFittedMesh::interpolate(const std::vector<double> &T, const double s)
  {
    const unsigned int n = T.size() - 1;
    const double       x = s * n;
    const double       j = std::round(x);
    // Coarse vertices (and so the contact edge) map exactly.
    if (std::abs(x - j) < 1e-9)
      return T[static_cast<unsigned int>(j)];
    const unsigned int k = std::min(static_cast<unsigned int>(x), n - 1);
    return T[k] + (x - k) * (T[k + 1] - T[k]);
  }

  void
  NipFittedMesh::build(parallel::distributed::Triangulation<dim> &triangulation,
                       const double                               theta0)
  {
    const auto        &m        = parameters.mesh;
    const unsigned int n_radial = radial_steps(parameters, 1.).size();
    // The logical square [0, 1]^2 with uniform coarse cells, refined while
    // flat: the fine vertices are the exact tensor grid of the coarse one.
    Triangulation<dim> coarse;
    GridGenerator::subdivided_hyper_rectangle(
      coarse,
      std::vector<unsigned int>{n_radial, n_cells},
      Point<dim>(0., 0.),
      Point<dim>(1., 1.),
      /*colorize=*/true);
    // The layer of each coarse cell, from its radial index.
    const std::vector<unsigned int> counts = layer_cell_counts(parameters);
    for (const auto &cell : coarse.active_cell_iterators())
      {
        unsigned int k = std::floor(cell->center()[0] * n_radial), layer = 0;
        while (k >= counts[layer])
          k -= counts[layer++];
        cell->set_material_id(layer);
      }
    triangulation.copy_triangulation(coarse);
    triangulation.refine_global(m.global_refinements);
    // The cells about the contact edge, halved again and again: the
    // displacement there is singular (the pressure's square root), and the
    // size of the cells at the edge sets the first-order error of
    // P(theta0) (doc/accuracy.md, "Refinement at the contact edge"). Done
    // in logical coordinates, so the levels stay nested.
    const Point<dim> edge(1., double(n_nip_cells) / n_cells);
    for (unsigned int k = 0; k < m.edge_refinements; ++k)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int v : cell->vertex_indices())
              if (cell->vertex(v).distance(edge) < 1e-12)
                cell->set_refine_flag();
        triangulation.execute_coarsening_and_refinement();
      }
    logical = triangulation.get_vertices();

    fit(triangulation, theta0);
    triangulation.set_all_manifold_ids(ManifoldIds::polar);
    triangulation.set_manifold(ManifoldIds::polar,
                               PolarManifold<dim>(Point<dim>()));
  }

  void
  NipFittedMesh::fit(parallel::distributed::Triangulation<dim> &triangulation,
                     const double                               theta0) const
  {
    Assert(theta0 > 0 && theta0 <= max_nip_angle() * (1 + 1e-12),
           ExcInternalError());
    const std::vector<double> T = coarse_angles(theta0);
    const std::vector<double> R = coarse_radii(theta0);
    std::vector<bool>         moved(logical.size(), false);
    for (const auto &cell : triangulation.cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        {
          const unsigned int i = cell->vertex_index(v);
          if (moved[i])
            continue;
          moved[i]        = true;
          const double r  = interpolate(R, logical[i][0]);
          const double a  = interpolate(T, logical[i][1]);
          cell->vertex(v) = Point<dim>(r * std::cos(a), r * std::sin(a));
        }
    triangulation.signals.mesh_movement();
  }
} // namespace rollnip
