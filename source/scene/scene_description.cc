#include <rollnip/global.h>
#include <rollnip/material/mooney_rivlin_law.h>
#include <rollnip/scene/scene_description.h>

#include <cmath>
#include <limits>

namespace rollnip
{
  double
  LayerDescription::shear_modulus() const
  {
    // The theory does not change the modulus.
    return MooneyRivlinLaw<dim>(C1, C2).shear_modulus();
  }

  double
  LayerDescription::youngs_modulus() const
  {
    return hardness_modulus > 0 ? hardness_modulus : 3 * shear_modulus();
  }

  double
  SceneDescription::counter_radius() const
  {
    if (const auto *circle = std::get_if<CounterKind::RigidCircle>(&counter))
      return circle->radius;
    if (const RollDescription *mate = covered_mate())
      return mate->outer_radius();
    return std::numeric_limits<double>::infinity();
  }

  const RollDescription *
  SceneDescription::covered_mate() const
  {
    const auto *covered = std::get_if<CounterKind::CoveredRoll>(&counter);
    return covered ? &covered->roll : nullptr;
  }

  RollDescription
  describe_roll(const Parameters::Geometry &geometry,
                const Parameters::Mesh     &mesh,
                const Parameters::Material &material)
  {
    RollDescription roll;
    roll.geometry = geometry;
    roll.mesh     = mesh;
    if (material.hardness_modulus > 0)
      roll.hardness_source = material.hardness_description;
    const unsigned int n = material.n_layers();
    for (unsigned int j = 0; j < n; ++j)
      {
        LayerDescription layer;
        layer.thickness = material.layer_thicknesses.empty()
                            ? roll.cover_thickness()
                            : material.layer_thicknesses[j];
        layer.C1        = material.layer_C1[j];
        layer.C2        = material.layer_C2[j];
        // The parameters keep the surface layer's modulus from hardness;
        // the layers below have E = 3 G, the same modulus.
        if (j + 1 == n)
          layer.hardness_modulus = material.hardness_modulus;
        roll.layers.push_back(layer);
      }
    return roll;
  }

  SceneDescription
  describe_scene(const Parameters::AllParameters &p)
  {
    SceneDescription scene;
    scene.roll     = describe_roll(p.geometry, p.mesh, p.material);
    scene.analysis = {p.material.theory, p.discretization.element};
    if (p.mating_roll.covered)
      scene.counter =
        CounterKind::CoveredRoll{describe_roll(p.mating_roll.geometry,
                                               p.mating_roll.mesh,
                                               p.mating_roll.material),
                                 p.mating_roll.max_iterations};
    else if (std::isinf(p.contact.indenter_radius))
      scene.counter = CounterKind::Plane{};
    else
      scene.counter = CounterKind::RigidCircle{p.contact.indenter_radius};
    return scene;
  }
} // namespace rollnip
