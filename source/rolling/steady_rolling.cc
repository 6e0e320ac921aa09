#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <rollnip/fe_fields.h>
#include <rollnip/material/law_factory.h>
#include <rollnip/rolling/steady_rolling.h>

#include <cmath>

namespace rollnip
{
  SteadyRolling::SteadyRolling(const SteadyRollingScene &scene)
      : scene(scene)
      , layout(scene.layout)
      , mapping(1)
      , fe(FE_Q<dim>(1), dim, FE_DGP<dim>(0), 1)
      , dof_handler(triangulation)
  {
    AssertThrow(scene.material.n_layers() + 1 ==
                  scene.layout.layer_radii.size(),
                ExcMessage("Steady rolling: one radius per layer boundary"));
    for (unsigned int l = 0; l < scene.material.n_layers(); ++l)
      laws.push_back(make_layer_law(scene.material, l));
    setup();
  }

  SteadyRolling::~SteadyRolling()
  {
    dof_handler.clear();
  }

  /// DoFs, the bond and surface nodes, the sparsity (the constraints only
  /// couple the DoFs of one node, which the pattern has) and the samples.
  void
  SteadyRolling::setup()
  {
    layout.create(triangulation);
    dof_handler.distribute_dofs(fe);
    const double R1 = layout.radii().front(), R0 = layout.radii().back();
    const double tolerance = 1e-9 * R0;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (const unsigned int v : cell->vertex_indices())
          {
            const Point<dim>              X = cell->vertex(v);
            const types::global_dof_index x = cell->vertex_dof_index(v, 0);
            const types::global_dof_index y = cell->vertex_dof_index(v, 1);
            if (std::abs(X.norm() - R1) < tolerance)
              bond_dofs.insert(bond_dofs.end(), {x, y});
            if (std::abs(X.norm() - R0) < tolerance)
              surface[x] = SurfaceNode{{{x, y}}, X};
          }
      }
    std::sort(bond_dofs.begin(), bond_dofs.end());
    bond_dofs.erase(std::unique(bond_dofs.begin(), bond_dofs.end()),
                    bond_dofs.end());
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp);
    pattern.copy_from(dsp);
    matrix.reinit(pattern);
    rhs.reinit(dof_handler.n_dofs());
    reactions.reinit(dof_handler.n_dofs());
    solution.reinit(dof_handler.n_dofs());
    make_samples();
  }

  /// The samples (cell centre along theta, radial Gauss line a) and the
  /// circles through them: circle 2 j + a of ring j holds the samples of
  /// radial index a, by sector. A sample's weight is that of the 2 x 2
  /// Gauss points on its line (unit x radial and fastest).
  void
  SteadyRolling::make_samples()
  {
    const unsigned int n = layout.n_sectors();
    FEValues<dim>      fe_values(mapping,
                            fe,
                            FEFields::cell_quadrature(fe),
                            update_JxW_values);
    FEValues<dim>      at_samples(mapping,
                             fe,
                             circle_quadrature(1).points[1],
                             update_quadrature_points);
    AssertThrow(fe_values.n_quadrature_points == 4 &&
                  at_samples.n_quadrature_points == 2,
                ExcInternalError());
    samples.resize(triangulation.n_active_cells() * 2);
    circle_samples.assign(2 * layout.n_rings(), std::vector<unsigned int>(n));
    circle_weight.assign(circle_samples.size(), 0.);
    circle_dissipation.assign(circle_samples.size(), 0.);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        const unsigned int j = c / n, i = c % n;
        const Point<dim>   expected(layout.radii()[j] *
                                    std::cos(layout.angles()[i]),
                                  layout.radii()[j] *
                                    std::sin(layout.angles()[i]));
        AssertThrow(cell->vertex(0).distance(expected) <
                      1e-9 * layout.radii().back(),
                    ExcMessage("Steady rolling: the cells are not in the "
                               "order of the rings"));
        fe_values.reinit(cell);
        at_samples.reinit(cell);
        for (unsigned int a = 0; a < 2; ++a)
          {
            Sample    &s = samples[2 * c + a];
            const auto X = at_samples.quadrature_point(a);
            s.theta      = std::atan2(X[1], X[0]);
            s.radius     = X.norm();
            s.layer      = cell->material_id();
            s.JxW        = fe_values.JxW(a) + fe_values.JxW(a + 2);
            circle_samples[2 * j + a][i] = 2 * c + a;
            circle_weight[2 * j + a] += s.JxW / (2. * numbers::PI);
          }
      }
  }

  std::vector<MaterialCircle>
  SteadyRolling::circles() const
  {
    std::vector<PolarTensor> S, E;
    point_fields(S, E);
    std::vector<MaterialCircle> result;
    for (unsigned int k = 0; k < circle_samples.size(); ++k)
      {
        MaterialCircle circle{circle_radius(k), circle_weight[k], 0, {}};
        for (const unsigned int s : circle_samples[k])
          {
            circle.layer = samples[s].layer;
            circle.samples.push_back({samples[s].theta, E[s], S[s]});
          }
        result.push_back(std::move(circle));
      }
    return result;
  }

  double
  SteadyRolling::circle_radius(const unsigned int k) const
  {
    const unsigned int j = k / 2, a = k % 2;
    const double       r0 = layout.radii()[j], r1 = layout.radii()[j + 1];
    return r0 + circle_quadrature(1).radial_coordinate[a] * (r1 - r0);
  }

  std::vector<CircleLoss>
  SteadyRolling::heat_source() const
  {
    std::vector<CircleLoss> source;
    for (unsigned int k = 0; k < circle_samples.size(); ++k)
      source.push_back({circle_radius(k),
                        circle_weight[k],
                        samples[circle_samples[k][0]].layer,
                        circle_dissipation[k],
                        0.});
    return source;
  }
} // namespace rollnip
