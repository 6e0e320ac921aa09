// The law of a cover whose moduli are s times its layer's (a cover
// softened by its temperature, doc/rolling.md):
// - ScaledLaw(Mooney-Rivlin(C1, C2), s) is Mooney-Rivlin(s C1, s C2) in
//   every evaluation (P, dP[dF], dP/dq, c, sigma, sigma_zz, G), and
//   ScaledLaw(linear(G), s) the linear law of s G: an independent law of
//   the scaled constants is the truth;
// - s = 1 gives the base law's values to the last bit (a cover that does
//   not soften reproduces today's nip to round-off);
// - MaterialTable::law() gives a cell its layer's law times the modulus
//   factor at its centre, and the factor 1 without one.

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <rollnip/material/linear_elastic_law.h>
#include <rollnip/material/material_table.h>
#include <rollnip/material/mooney_rivlin_law.h>
#include <rollnip/material/scaled_law.h>

#include "random_tensor.h"
#include "test_tools.h"

#include <random>

using namespace rollnip;
using testing::random_tensor;

namespace
{
  /// The largest difference of every evaluation of @p a and @p b at
  /// (F, q) along dF.
  double
  difference(const MaterialLaw<dim> &a,
             const MaterialLaw<dim> &b,
             const Tensor<2, dim>   &F,
             const double            q,
             const Tensor<2, dim>   &dF)
  {
    return std::max(
      {(a.piola(F, q) - b.piola(F, q)).norm(),
       (a.piola_derivative(F, q, dF) - b.piola_derivative(F, q, dF)).norm(),
       (a.pressure_direction(F) - b.pressure_direction(F)).norm(),
       std::abs(a.constraint(F) - b.constraint(F)),
       (a.cauchy(F, q) - b.cauchy(F, q)).norm(),
       std::abs(a.out_of_plane_stress(F, q) - b.out_of_plane_stress(F, q)),
       std::abs(a.shear_modulus() - b.shear_modulus())});
  }

  /// MaterialTable::law(): a 2 x 2 grid of cells, the factor 1 + x + 2 y
  /// at the centre of each.
  void
  check_table(testing::Checker &check)
  {
    Triangulation<dim> mesh;
    GridGenerator::subdivided_hyper_cube(mesh, 2);
    Parameters::Material m;
    m.layer_C1 = {0.5};
    m.layer_C2 = {0.1};
    m.theory   = Parameters::Theory::nonlinear;
    MaterialTable table(m);
    double        d_none = 0, d_factor = 0;
    for (const auto &cell : mesh.active_cell_iterators())
      d_none = std::max(d_none, std::abs(table.law(*cell).factor() - 1.));
    table.set_modulus_factor([](const Point<dim> &X, const types::material_id) {
      return 1. + X[0] + 2. * X[1];
    });
    for (const auto &cell : mesh.active_cell_iterators())
      {
        const Point<dim> c = cell->center();
        const double     s = 1. + c[0] + 2. * c[1];
        d_factor =
          std::max({d_factor,
                    std::abs(table.law(*cell).factor() - s),
                    std::abs(table.law(*cell).shear_modulus() - s * 1.2)});
      }
    check.check(d_none == 0 && d_factor < 1e-15,
                "MaterialTable::law(): factor 1 without a modulus factor "
                "(diff " +
                  testing::num(d_none) +
                  "), the factor at each cell's centre with one (diff " +
                  testing::num(d_factor) + ")");
  }
} // namespace

int
main()
{
  testing::Checker     check;
  std::mt19937         gen(7);
  const double         C1 = 0.45, C2 = 0.12;
  const Tensor<2, dim> I = unit_symmetric_tensor<dim>();

  double d_finite = 0, d_linear = 0, d_one = 0;
  for (unsigned int sample = 0; sample < 40; ++sample)
    {
      const double   s = std::uniform_real_distribution<>(0.3, 1.7)(gen);
      const double   q = std::uniform_real_distribution<>(-2, 2)(gen);
      Tensor<2, dim> F = I + random_tensor<dim>(gen, 0.4);
      if (determinant(F) < 0.3)
        F = I;
      const Tensor<2, dim> dF = random_tensor<dim>(gen, 1.);

      const MooneyRivlinLaw<dim> base(C1, C2), scaled(s * C1, s * C2);
      d_finite =
        std::max(d_finite,
                 difference(ScaledLaw<dim>(base, s), scaled, F, q, dF) /
                   (s * 2 * (C1 + C2) + std::abs(q)));
      const LinearElasticLaw<dim> lin(2 * (C1 + C2)),
        lin_scaled(s * 2 * (C1 + C2));
      d_linear =
        std::max(d_linear,
                 difference(ScaledLaw<dim>(lin, s), lin_scaled, F, q, dF) /
                   (s * 2 * (C1 + C2) + std::abs(q)));
      d_one = std::max({d_one,
                        difference(ScaledLaw<dim>(base, 1.), base, F, q, dF),
                        difference(ScaledLaw<dim>(lin, 1.), lin, F, q, dF)});
    }
  check.check(d_finite < 1e-14,
              "ScaledLaw(Mooney-Rivlin(C1, C2), s) = Mooney-Rivlin(s C1, "
              "s C2): max relative diff " +
                testing::num(d_finite));
  check.check(d_linear < 1e-14,
              "ScaledLaw(linear(G), s) = linear(s G): max relative diff " +
                testing::num(d_linear));
  check.check(d_one == 0,
              "s = 1: every value the base law's to the last bit (max diff " +
                testing::num(d_one) + ")");
  check_table(check);
  return check.result();
}
