#ifndef rollnip_scene_scene_validation_h
#define rollnip_scene_scene_validation_h

#include <rollnip/parameters.h>

#include <string>
#include <vector>

namespace rollnip
{
  /**
   * Where a roll's contact edge will lie, as far as it is known before the
   * run: its angles [rad] from the line of centres, each with the words
   * that say where it comes from ("Contact/Values = 8 deg"), and whether
   * they are estimates (the mating roll's, from the first roll's theta0).
   */
  struct NipReach
  {
    std::vector<double>      angles;
    std::vector<std::string> sources;
    bool                     estimated = false;
  };

  /// The layers of a roll's cover (@p material on @p geometry): their
  /// count in every entry, their constants and thicknesses; entries named
  /// with @p prefix ("" or "Mating roll/").
  void
  validate_cover(const Parameters::Material &material,
                 const Parameters::Geometry &geometry,
                 const std::string          &prefix);

  /**
   * The checks of one roll of a scene, the same code for the first roll
   * (@p prefix "") and the covered mating roll (@p prefix "Mating roll/",
   * @p roll its scene, AllParameters::mating_roll_parameters()): geometry,
   * material, mesh entries, the gmsh mesh, and whether the mesh reaches
   * @p nips (half the sector on the nip-fitted mesh). Every message names
   * the entries by their full paths. Returns the roll's coarse cells, for
   * the cost of the scene.
   */
  double
  validate_roll(const Parameters::AllParameters &roll,
                const std::string               &prefix,
                const NipReach                  &nips);

  /// The largest line load [N/mm] taken as a target, over the largest
  /// shear modulus G of the covers times the roll's outer radius R0: far
  /// beyond what a cover carries (P / (G R0) is below 1 at a nip of half
  /// a right angle on the default scene).
  constexpr double max_load_over_G_R0 = 1000;

  /**
   * The targets of Contact/Values as the program uses them, whether typed
   * or derived (a total force over Contact/Face length, a line load in
   * kN/m or pli): finite line loads up to max_load_over_G_R0 G R0 under
   * load control, indentations below the covers' thickness (the approach
   * at which the core would touch the mate) under indentation control.
   * The message names what the value came from.
   */
  void
  validate_targets(const Parameters::AllParameters &parameters);

  /// Both rolls of @p parameters with validate_roll(), then the size of
  /// the whole scene (check_cost()) and a warning for a roll whose size
  /// suggests lengths typed in another unit than mm.
  void
  validate_rolls(const Parameters::AllParameters &parameters);
} // namespace rollnip

#endif
