// The laws behind MaterialLaw and the factory that picks them per layer.
// - The linear-theory law is the linearisation of the Mooney-Rivlin law at
//   the reference state: the same P(I, q) = q I, the same dP[H] for every
//   isochoric (traceless) H, the same dP/dq = I there, and constraints that
//   differ by exactly det(eps H) = eps^2 det H along F = I + eps H.
// - make_layer_law() gives each layer its own constants and the theory's
//   law (Theory = linear: P linear in F), and MaterialTable looks a cell's
//   layer up by material id.
// - commit() and rollback() of the elastic laws change no evaluation.

#include <rollnip/material/law_factory.h>
#include <rollnip/material/linear_elastic_law.h>
#include <rollnip/material/material_table.h>
#include <rollnip/material/mooney_rivlin_law.h>

#include "random_tensor.h"
#include "test_tools.h"

#include <random>

using namespace rollnip;
using testing::random_tensor;

namespace
{
  Parameters::Material
  two_layers(const Parameters::Theory theory)
  {
    Parameters::Material m;
    m.layer_C1 = {0.8, 0.3};
    m.layer_C2 = {0.1, 0.05};
    m.theory   = theory;
    return m;
  }
  /// The factory: per-layer constants, the theory's law; the linear law
  /// affine in F; commit() and rollback() of an elastic law.
  void
  check_factory(testing::Checker &check, std::mt19937 &gen)
  {
    const Tensor<2, dim> I  = unit_symmetric_tensor<dim>();
    const Tensor<2, dim> F  = I + random_tensor<dim>(gen, 0.3);
    const Tensor<2, dim> dF = random_tensor<dim>(gen, 1.);
    for (const auto theory :
         {Parameters::Theory::nonlinear, Parameters::Theory::linear})
      {
        const Parameters::Material m = two_layers(theory);
        MaterialTable              table(m);
        const bool                 lin   = theory == Parameters::Theory::linear;
        const std::string          name  = lin ? "linear" : "nonlinear";
        double                     d_law = 0;
        for (unsigned int j = 0; j < 2; ++j)
          {
            const auto           law = make_layer_law(m, j);
            const double         Gj  = 2 * (m.layer_C1[j] + m.layer_C2[j]);
            const Tensor<2, dim> expected =
              lin ? LinearElasticLaw<2>(Gj).piola(F, 0.7)
                  : MooneyRivlinLaw<2>(m.layer_C1[j], m.layer_C2[j])
                      .piola(F, 0.7);
            d_law = std::max({d_law,
                              (law->piola(F, 0.7) - expected).norm(),
                              (table[j].piola(F, 0.7) - expected).norm(),
                              std::abs(table[j].shear_modulus() - Gj)});
          }
        check.check(d_law < 1e-15 && table.n_layers() == 2 &&
                      table.is_linear() == lin,
                    name +
                      " theory: each layer's law and modulus from the "
                      "factory and the table, max diff " +
                      testing::num(d_law));
        // Linear theory: P is affine in F, so dP[dF] = P(F + dF) - P(F).
        const double affine =
          (table[1].piola(F + dF, 0.7) - table[1].piola(F, 0.7) -
           table[1].piola_derivative(F, 0.7, dF))
            .norm() /
          dF.norm();
        check.check(lin ? affine < 1e-14 : affine > 1e-3,
                    name + " theory: |P(F + dF) - P(F) - dP[dF]| / |dF| = " +
                      testing::num(affine) +
                      (lin ? " (affine law)" : " (nonlinear law)"));

        const Tensor<2, dim> before = table[0].piola(F, 0.7);
        table.commit();
        const Tensor<2, dim> committed = table[0].piola(F, 0.7);
        table.rollback();
        const Tensor<2, dim> rolled_back = table[0].piola(F, 0.7);
        check.check((committed - before).norm() == 0 &&
                      (rolled_back - before).norm() == 0,
                    name + " theory: commit() and rollback() leave the "
                           "elastic law unchanged");
      }
  }
} // namespace

int
main()
{
  testing::Checker          check;
  std::mt19937              gen(23);
  const double              C1 = 0.4, C2 = 0.15, G = 2 * (C1 + C2);
  const MooneyRivlinLaw<2>  finite(C1, C2);
  const LinearElasticLaw<2> linear(G);
  const Tensor<2, dim>      I = unit_symmetric_tensor<dim>();

  double d_P0 = 0, d_dP = 0, d_dir = 0, d_c = 0;
  for (unsigned int sample = 0; sample < 40; ++sample)
    {
      Tensor<2, dim> H = random_tensor<dim>(gen, 1.);
      H -= 0.5 * trace(H) * I; // isochoric
      const double q         = std::uniform_real_distribution<>(-2, 2)(gen);
      const double eps       = 1e-3;
      d_P0                   = std::max(d_P0,
                      (finite.piola(I, q) - q * I).norm() +
                        (linear.piola(I, q) - q * I).norm());
      d_dP                   = std::max(d_dP,
                      (finite.piola_derivative(I, 0., H) -
                       linear.piola_derivative(I, 0., H))
                          .norm() /
                        (G * H.norm()));
      d_dir                  = std::max(d_dir,
                       (finite.pressure_direction(I) - I).norm() +
                         (linear.pressure_direction(I + eps * H) - I).norm());
      const Tensor<2, dim> F = I + eps * H;
      d_c                    = std::max(d_c,
                     std::abs(finite.constraint(F) - linear.constraint(F) -
                              eps * eps * determinant(H)) /
                       (eps * eps));
    }
  check.check(d_P0 < 1e-14,
              "P(I, q) = q I for both laws: max diff " + testing::num(d_P0));
  check.check(d_dP < 1e-14,
              "dP[H] at (I, 0), isochoric H: linear law against "
              "Mooney-Rivlin, max diff / (G |H|) " +
                testing::num(d_dP));
  check.check(d_dir < 1e-14,
              "dP/dq = I at the reference (and for the linear law "
              "everywhere): max diff " +
                testing::num(d_dir));
  check.check(d_c < 1e-9,
              "(J - 1) - tr(F - I) = eps^2 det H along F = I + eps H: max "
              "diff / eps^2 " +
                testing::num(d_c));

  check_factory(check, gen);
  return check.result();
}
