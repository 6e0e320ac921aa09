#include <deal.II/base/numbers.h>

#include <deal.II/grid/tria_description.h>

#include <rollnip/boundary_ids.h>
#include <rollnip/rolling/annulus_mesh.h>

#include <algorithm>
#include <cmath>

namespace rollnip
{
  namespace
  {
    /// Node angles of the half 0 <= theta <= pi: uniform steps @p h up to
    /// @p fine, then steps growing by @p growth, the last stretch scaled to
    /// end at pi exactly.
    std::vector<double>
    half_angles(const double h, const double fine, const double growth)
    {
      std::vector<double> a;
      const unsigned int  n_fine = std::lround(fine / h);
      for (unsigned int i = 0; i <= n_fine; ++i)
        a.push_back(i * h);
      double step = h;
      while (a.back() + step * growth < numbers::PI - 0.5 * step * growth)
        {
          step *= growth;
          step = std::min(step, numbers::PI / 8);
          a.push_back(a.back() + step);
        }
      // Stretch the coarse part so that the last node is pi.
      const double start = a[n_fine],
                   scale = (numbers::PI - start) / (a.back() + step - start);
      for (unsigned int i = n_fine + 1; i < a.size(); ++i)
        a[i] = start + (a[i] - start) * scale;
      a.push_back(numbers::PI);
      return a;
    }

    /// Radii of @p n cells from @p r0 to @p r1, the last over the first
    /// @p grading.
    std::vector<double>
    graded(const double r0, const double r1, const unsigned n, double grading)
    {
      const double        q = n > 1 ? std::pow(grading, 1. / (n - 1)) : 1.;
      std::vector<double> w(n, 1.);
      for (unsigned int k = 1; k < n; ++k)
        w[k] = w[k - 1] * q;
      double total = 0;
      for (const double x : w)
        total += x;
      std::vector<double> r{r0};
      for (unsigned int k = 0; k < n; ++k)
        r.push_back(r.back() + (r1 - r0) * w[k] / total);
      r.back() = r1;
      return r;
    }
  } // namespace

  AnnulusMesh::AnnulusMesh(const AnnulusLayout &layout)
  {
    const auto  &lr   = layout.layer_radii;
    const double h    = 2. * layout.fine_half_angle / layout.fine_cells;
    const auto   half = half_angles(h, layout.fine_half_angle, layout.growth);
    // -pi (= pi), ..., -h, 0, h, ..., the last before pi.
    for (unsigned int i = half.size() - 1; i > 0; --i)
      node_angles.push_back(-half[i]);
    node_angles.insert(node_angles.end(), half.begin(), half.end() - 1);

    const unsigned int n_layers = lr.size() - 1;
    const double       cover    = lr.back() - lr.front();
    node_radii.push_back(lr.front());
    for (unsigned int l = 0; l < n_layers; ++l)
      {
        const unsigned int n = std::max<unsigned int>(
          1, std::lround(layout.radial_cells * (lr[l + 1] - lr[l]) / cover));
        const auto r = graded(lr[l], lr[l + 1], n, layout.radial_grading);
        node_radii.insert(node_radii.end(), r.begin() + 1, r.end());
        layer_of_ring.insert(layer_of_ring.end(), n, l);
      }
  }

  void
  AnnulusMesh::create(Triangulation<dim> &tria) const
  {
    const unsigned int      n = n_sectors(), m = node_radii.size();
    std::vector<Point<dim>> vertices;
    for (unsigned int j = 0; j < m; ++j)
      for (unsigned int i = 0; i < n; ++i)
        vertices.emplace_back(node_radii[j] * std::cos(node_angles[i]),
                              node_radii[j] * std::sin(node_angles[i]));
    std::vector<CellData<dim>> cells;
    for (unsigned int j = 0; j + 1 < m; ++j)
      for (unsigned int i = 0; i < n; ++i)
        {
          CellData<dim>      c;
          const unsigned int next = (i + 1) % n;
          // Unit x outward, unit y along theta: positively oriented.
          c.vertices    = {j * n + i,
                           (j + 1) * n + i,
                           j * n + next,
                           (j + 1) * n + next};
          c.material_id = layer_of_ring[j];
          cells.push_back(c);
        }
    tria.create_triangulation(vertices, cells, SubCellData());
    // The builtin mesh's ids: the bond and the surface (the temperature's
    // boundary conditions, CoverTemperature). A face's vertices lie on its
    // circle (its centre, on the chord, does not).
    const double middle = 0.5 * (node_radii.front() + node_radii.back());
    for (const auto &cell : tria.cell_iterators_on_level(0))
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          cell->face(f)->set_boundary_id(
            cell->face(f)->vertex(0).norm() > middle ? BoundaryIds::outer_arc
                                                     : BoundaryIds::inner_arc);
  }
} // namespace rollnip
