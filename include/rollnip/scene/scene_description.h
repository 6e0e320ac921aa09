#ifndef rollnip_scene_scene_description_h
#define rollnip_scene_scene_description_h

#include <rollnip/parameters.h>

#include <string>
#include <variant>
#include <vector>

namespace rollnip
{
  /// One layer of a cover: its thickness and its Mooney-Rivlin law, with
  /// the modulus the user gave if it came from a hardness reading.
  struct LayerDescription
  {
    double thickness; ///< [mm]
    double C1, C2;    ///< [MPa]
    /// Young's modulus [MPa] the hardness reading gave (which then set C1
    /// and C2); 0: C1 and C2 were given.
    double hardness_modulus = 0;

    /// G = 2 (C1 + C2) [MPa], the law's (MaterialLaw::shear_modulus).
    double
    shear_modulus() const;

    /// E [MPa]: the one from hardness when that was the input, else 3 G
    /// (incompressible).
    double
    youngs_modulus() const;
  };

  /// A covered roll, described once: its geometry, its mesh and its
  /// layers from the core out.
  struct RollDescription
  {
    Parameters::Geometry          geometry;
    Parameters::Mesh              mesh;
    std::vector<LayerDescription> layers;
    /// The hardness reading and relation, e.g. "60 Shore A, Gent (1958)";
    /// empty when C1 and C2 were given.
    std::string hardness_source;

    double
    outer_radius() const
    {
      return geometry.outer_radius;
    }

    double
    cover_thickness() const
    {
      return geometry.outer_radius - geometry.inner_radius;
    }

    /// The layer on the outer surface, whose modulus the contact
    /// estimates use.
    const LayerDescription &
    surface_layer() const
    {
      return layers.back();
    }

    bool
    modulus_from_hardness() const
    {
      return !hardness_source.empty();
    }
  };

  /// The counter surface of a contact scene: one of the three below.
  namespace CounterKind
  {
    /// A rigid circle of radius R [mm].
    struct RigidCircle
    {
      double radius;
    };

    /// A rigid plane.
    struct Plane
    {
    };

    /// A second covered roll, both deformable (TwoRollContact).
    struct CoveredRoll
    {
      RollDescription roll;
      /// Outer iterations between the two rolls per nip.
      unsigned int max_iterations;
    };
  } // namespace CounterKind

  using Counter = std::variant<CounterKind::RigidCircle,
                               CounterKind::Plane,
                               CounterKind::CoveredRoll>;

  /// The choices of the analysis, one for every body of the scene.
  struct Analysis
  {
    Parameters::Theory  theory;
    Parameters::Element element;
  };

  /**
   * A scene described once: the roll, what it is pressed against, and the
   * analysis. Filled from the parameters by describe_scene() and not
   * changed afterwards; every run builds its bodies and counter surface
   * from it (scene/scene_builder.h).
   */
  struct SceneDescription
  {
    RollDescription roll;
    Counter         counter;
    Analysis        analysis;

    /// The radius of the counter surface [mm]: the rigid circle's, the
    /// covered roll's outer radius, infinity for the plane.
    double
    counter_radius() const;

    /// The covered mating roll; nullptr against a rigid counter surface.
    const RollDescription *
    covered_mate() const;
  };

  /// The roll of @p geometry, @p mesh and @p material.
  RollDescription
  describe_roll(const Parameters::Geometry &geometry,
                const Parameters::Mesh     &mesh,
                const Parameters::Material &material);

  /// The scene of @p parameters (the only place it is derived from them).
  SceneDescription
  describe_scene(const Parameters::AllParameters &parameters);
} // namespace rollnip

#endif
