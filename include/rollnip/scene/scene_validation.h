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

  /// Both rolls of @p parameters with validate_roll(), then the size of
  /// the whole scene (check_cost()) and a warning for a roll whose size
  /// suggests lengths typed in another unit than mm.
  void
  validate_rolls(const Parameters::AllParameters &parameters);
} // namespace rollnip

#endif
