#include <rollnip/geometry/cover_layers.h>
#include <rollnip/geometry/roll_mesh.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace rollnip
{
  std::vector<double>
  layer_radii(const Parameters::AllParameters &parameters)
  {
    const auto         &g = parameters.geometry;
    std::vector<double> radii{g.inner_radius};
    for (const double t : parameters.material.layer_thicknesses)
      radii.push_back(radii.back() + t);
    if (radii.size() == 1)
      radii.push_back(g.outer_radius);
    radii.back() = g.outer_radius; // exactly: the surface
    return radii;
  }

  std::vector<unsigned int>
  layer_cell_counts(const Parameters::AllParameters &parameters)
  {
    const std::vector<double> radii    = layer_radii(parameters);
    const unsigned int        n_layers = radii.size() - 1;
    const unsigned int n = std::max(parameters.mesh.radial_cells, n_layers);
    const double       h = radii.back() - radii.front();
    std::vector<unsigned int> counts(n_layers);
    unsigned int              total = 0;
    for (unsigned int j = 0; j < n_layers; ++j)
      total += counts[j] = std::max(1u,
                                    static_cast<unsigned int>(std::lround(
                                      n * (radii[j + 1] - radii[j]) / h)));
    // Rounding may miss n: the thickest layer per cell gives or takes.
    while (total != n)
      {
        unsigned int pick = 0;
        double       best = total < n ? -1. : 1e300;
        for (unsigned int j = 0; j < n_layers; ++j)
          {
            const double width = (radii[j + 1] - radii[j]) / counts[j];
            if (total < n ? width > best : (counts[j] > 1 && width < best))
              best = width, pick = j;
          }
        if (total < n)
          ++counts[pick], ++total;
        else
          --counts[pick], --total;
      }
    return counts;
  }

  double
  stiff_layer_grading(const Parameters::AllParameters &parameters,
                      const unsigned int               layer)
  {
    const auto &m = parameters.material;
    if (layer == 0 || layer >= m.n_layers())
      return 1.;
    const double G_below = m.layer_C1[layer - 1] + m.layer_C2[layer - 1];
    const double G       = m.layer_C1[layer] + m.layer_C2[layer];
    return G > G_below ? std::pow(G_below / G, 0.25) : 1.;
  }

  std::vector<double>
  radial_steps(const Parameters::AllParameters &parameters, const double ratio)
  {
    const std::vector<double>       radii  = layer_radii(parameters);
    const std::vector<unsigned int> counts = layer_cell_counts(parameters);
    unsigned int                    n      = 0;
    for (const unsigned int c : counts)
      n += c;
    // One grading for the whole cover; each layer takes its cells of it,
    // stretched to fill the layer, so that cell sizes change smoothly
    // through the interfaces and two equal layers are one layer.
    const std::vector<double> whole =
      graded_steps(n, radii.back() - radii.front(), ratio);
    std::vector<double> steps;
    unsigned int        k = 0;
    for (unsigned int j = 0; j < counts.size(); ++j)
      {
        const std::vector<double> extra =
          graded_steps(counts[j], 1., stiff_layer_grading(parameters, j));
        std::vector<double> mine;
        double              sum = 0;
        for (unsigned int i = 0; i < counts[j]; ++i)
          sum += mine.emplace_back(whole[k + i] * extra[i]);
        for (const double w : mine)
          steps.push_back(w * (radii[j + 1] - radii[j]) / sum);
        k += counts[j];
      }
    return steps;
  }

  unsigned int
  layer_at_radius(const std::vector<double> &radii, const double r)
  {
    const auto it = std::upper_bound(radii.begin() + 1, radii.end() - 1, r);
    return static_cast<unsigned int>(it - (radii.begin() + 1));
  }

  void
  set_layer_ids(const Parameters::AllParameters &parameters,
                Triangulation<dim>              &triangulation)
  {
    const std::vector<double> radii = layer_radii(parameters);
    for (const auto &cell : triangulation.active_cell_iterators())
      cell->set_material_id(layer_at_radius(radii, cell->center().norm()));
  }

  void
  check_layer_ids(const Parameters::AllParameters &parameters,
                  const Triangulation<dim>        &triangulation,
                  const std::string               &origin,
                  const std::string               &prefix)
  {
    const std::vector<double> radii    = layer_radii(parameters);
    const unsigned int        n_layers = radii.size() - 1;
    if (n_layers == 1)
      return; // every cell is the one layer, whatever its tag
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        const unsigned int id = cell->material_id();
        AssertThrow(id < n_layers,
                    ExcMessage(origin +
                               ": a cell has material (physical "
                               "surface) id " +
                               std::to_string(id) + ", but the cover has " +
                               std::to_string(n_layers) + " layers (ids 0 to " +
                               std::to_string(n_layers - 1) +
                               ", from the core out)"));
        const double r = cell->center().norm();
        AssertThrow(r > radii[id] && r < radii[id + 1],
                    ExcMessage(origin + ": a cell of layer " +
                               std::to_string(id) +
                               " (material id) has its "
                               "centre at radius " +
                               std::to_string(r) + " mm, outside the layer's " +
                               std::to_string(radii[id]) + " to " +
                               std::to_string(radii[id + 1]) + " mm (" +
                               prefix + "Material/Layer thicknesses)"));
      }
  }
} // namespace rollnip
