// The scene description (scene/scene_description.h) and the scene builder
// (scene/scene_builder.h):
//  - a two-roll scene describes each roll once: the roll's radius and the
//    mating roll's (125 and 200 mm from the diameters) are read from the
//    description, the counter radius is the mating roll's outer radius,
//    and Contact/Indenter radius keeps the value it was parsed with
//    (nothing is copied into it);
//  - a rigid scene has no covered mate: the circle of Indenter radius, or
//    the plane (infinite radius) for 'inf';
//  - the layers: one layer is the whole cover; two layers carry their
//    thicknesses and constants; G = 2 (C1 + C2) and E = 3 G from C1, C2;
//    from a hardness the surface layer's E is the hardness relation's
//    (Gent 1958 for Shore A) and G = E/3 to round-off;
//  - the effective radius of the estimates is 1/(1/R0 + 1/R_mate), the
//    contact modulus 1/(1/(4 G) + 1/(4 G_mate));
//  - the builder's counter surface has the description's radius, and the
//    nip solver it builds solves the described scene (rigid, or the
//    covered mate with no rigid surface).

#include <rollnip/contact/counter_surface.h>
#include <rollnip/contact/nip_estimates.h>
#include <rollnip/contact/nip_solver.h>
#include <rollnip/material/hardness.h>
#include <rollnip/scene/scene_builder.h>
#include <rollnip/scene/scene_description.h>

#include "test_tools.h"

#include <limits>
#include <variant>

using namespace rollnip;

namespace
{
  const std::string coarse =
    "subsection Mesh\n set Radial cells = 2\n set Circumferential cells = "
    "12\n set Global refinements = 0\nend\n";

  const std::string two_rolls =
    "subsection Geometry\n set Roll diameter = 250\n set Cover thickness = "
    "13.5\nend\n" +
    coarse +
    "subsection Material\n set Hardness = 60\n set Hardness scale = Shore "
    "A\n set C2/C1 ratio = 0\nend\n"
    "subsection Contact\n set Mode = nip angle\n set Values = 5\nend\n"
    "subsection Mating roll\n set Type = covered roll\n"
    " subsection Geometry\n  set Roll diameter = 400\n"
    "  set Cover thickness = 15\n end\n"
    " subsection Material\n  set C1 = 1.5, 0.5\n  set C2 = 0.25, 0\n"
    "  set Layer thicknesses = 5, 10\n end\n" +
    coarse + "end\n";

  bool
  close(const double a, const double b, const double tolerance = 1e-12)
  {
    return std::abs(a - b) <= tolerance * std::abs(b);
  }

  void
  two_roll_scene(testing::Checker &checker)
  {
    const auto             p     = testing::parameters_from_string(two_rolls);
    const SceneDescription scene = describe_scene(p);
    const RollDescription *mate  = scene.covered_mate();
    checker.check(mate != nullptr, "the two-roll scene has a covered mate");
    if (!mate)
      return;
    checker.check(scene.roll.outer_radius() == 125. &&
                    mate->outer_radius() == 200. &&
                    scene.counter_radius() == 200.,
                  "radii: roll " + testing::num(scene.roll.outer_radius()) +
                    " mm, mate " + testing::num(mate->outer_radius()) +
                    " mm, counter " + testing::num(scene.counter_radius()) +
                    " mm (125, 200, 200)");
    checker.check(p.contact.indenter_radius == 76.2,
                  "Contact/Indenter radius keeps its parsed 76.2 mm, got " +
                    testing::num(p.contact.indenter_radius));
    // The roll: one layer from hardness 60 Shore A.
    const double E = Hardness::youngs_modulus(60, Hardness::Scale::shore_a);
    const LayerDescription &top = scene.roll.surface_layer();
    checker.check(scene.roll.layers.size() == 1 && close(top.thickness, 13.5) &&
                    top.youngs_modulus() == E &&
                    close(top.shear_modulus(), E / 3) &&
                    scene.roll.modulus_from_hardness(),
                  "roll: one layer of 13.5 mm, E = " +
                    testing::num(top.youngs_modulus()) +
                    " MPa from 60 Shore "
                    "A, G = E/3");
    // The mate: two layers given by C1, C2.
    const auto &layers = mate->layers;
    checker.check(layers.size() == 2 && layers[0].thickness == 5 &&
                    layers[1].thickness == 10 &&
                    close(layers[0].shear_modulus(), 2 * (1.5 + 0.25)) &&
                    close(layers[1].shear_modulus(), 2 * 0.5) &&
                    close(layers[1].youngs_modulus(), 3 * 2 * 0.5) &&
                    !mate->modulus_from_hardness(),
                  "mate: layers 5 and 10 mm, G 3.5 and 1 MPa, surface E = "
                  "3 G = 3 MPa");
    const double R  = 1. / (1. / 125 + 1. / 200);
    const double Es = 1. / (1. / (4 * E / 3) + 1. / (4 * 1.));
    checker.check(close(NipEstimates::effective_radius(scene), R, 1e-14) &&
                    close(NipEstimates::contact_modulus(scene), Es, 1e-12),
                  "estimates: R = " +
                    testing::num(NipEstimates::effective_radius(scene)) +
                    " mm (" + testing::num(R) + "), E* = " +
                    testing::num(NipEstimates::contact_modulus(scene)) +
                    " MPa (" + testing::num(Es) + ")");
    const Scene built(p, MPI_COMM_WORLD);
    checker.check(built.rigid_counter_surface() == nullptr &&
                    built.description.counter_radius() == 200.,
                  "the builder: no rigid surface against the covered mate");
  }

  void
  rigid_scenes(testing::Checker &checker)
  {
    for (const std::string radius : {"90", "inf"})
      {
        const auto p = testing::parameters_from_string(
          coarse +
          "subsection Contact\n set Mode = nip angle\n set Values "
          "= 5\n set Indenter radius = " +
          radius + "\nend\n");
        const SceneDescription scene = describe_scene(p);
        const double           R =
          radius == "inf" ? std::numeric_limits<double>::infinity() : 90.;
        const bool kind =
          radius == "inf"
            ? std::holds_alternative<CounterKind::Plane>(scene.counter)
            : std::holds_alternative<CounterKind::RigidCircle>(scene.counter);
        checker.check(scene.covered_mate() == nullptr && kind &&
                        scene.counter_radius() == R,
                      "Indenter radius = " + radius +
                        ": no covered mate, counter radius " +
                        testing::num(scene.counter_radius()) + " mm");
        const LayerDescription &layer = scene.roll.surface_layer();
        checker.check(
          scene.roll.layers.size() == 1 &&
            close(layer.thickness, scene.roll.cover_thickness()) &&
            close(layer.youngs_modulus(),
                  3 * 2 * (p.material.layer_C1[0] + p.material.layer_C2[0])),
          "one layer, the whole cover, E = 6 (C1 + C2) = " +
            testing::num(layer.youngs_modulus()) + " MPa");
        const Scene           built(p, MPI_COMM_WORLD);
        const CounterSurface *surface = built.rigid_counter_surface();
        checker.check(surface != nullptr && surface->radius() == R,
                      "the builder's counter surface has radius " +
                        (surface ? testing::num(surface->radius()) : "none") +
                        " mm");
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  two_roll_scene(checker);
  rigid_scenes(checker);
  return checker.result();
}
