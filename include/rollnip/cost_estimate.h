#ifndef rollnip_cost_estimate_h
#define rollnip_cost_estimate_h

#include <rollnip/parameters.h>

namespace rollnip
{
  /// The size of one roll's mesh and of its direct solve.
  struct CostEstimate
  {
    unsigned int level;  ///< global refinements of the coarse mesh
    double       cells;  ///< after the refinements
    double       dofs;   ///< of the displacement and the pressure
    double       memory; ///< [bytes] of the factorised Newton matrix
  };

  /**
   * The size of a roll of @p parameters whose coarse mesh has
   * @p coarse_cells cells, refined @p level times: its DoFs and the memory
   * the sparse direct solver takes for them (measured at 2.6 to 3.7 kB per
   * DoF for Q1-P0 on the default scene, doc/accuracy.md); the element is
   * Q2-P1 if the file or Study/Elements uses it.
   */
  CostEstimate
  estimate_cost(const Parameters::AllParameters &parameters,
                const double                     coarse_cells,
                const unsigned int               level);

  /**
   * Refuses, before any mesh is refined, a run that cannot fit the
   * machine: the roll of @p coarse_cells cells refined Mesh/Global
   * refinements times (or the largest Study/Refinement levels), against
   * the physical memory. The one-line message carries the estimate. Not
   * checked for Linear solver/Method = gmres-amg (not measured).
   */
  void
  check_cost(const Parameters::AllParameters &parameters,
             const double                     coarse_cells);

  /**
   * The same for a scene with a covered mating roll of @p mate_coarse_cells
   * cells at its own Mating roll/Mesh/Global refinements: both rolls'
   * memory together against the machine's; the message names the
   * refinements of the roll that takes the larger part.
   */
  void
  check_cost(const Parameters::AllParameters &parameters,
             const double                     coarse_cells,
             const double                     mate_coarse_cells);

  /// The most nips one run takes (Contact/Values): each is at least one
  /// full contact solve.
  constexpr unsigned int max_nips_per_run = 1000;
} // namespace rollnip

#endif
