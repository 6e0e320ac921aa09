#ifndef rollnip_cost_estimate_h
#define rollnip_cost_estimate_h

#include <rollnip/parameters.h>

namespace rollnip
{
  /**
   * Refuses, before any mesh is refined, a run that cannot fit the
   * machine: the DoFs of @p coarse_cells cells refined Mesh/Global
   * refinements times (or the largest Study/Refinement levels), and the
   * memory the sparse direct solver takes for them (measured at 2.6 to 3.7
   * kB per DoF for Q1-P0 on the default scene, doc/accuracy.md), against
   * the physical memory. The one-line message carries the estimate. Not
   * checked for Linear solver/Method = gmres-amg (not measured).
   */
  void
  check_cost(const Parameters::AllParameters &parameters,
             const double                     coarse_cells);

  /// The most nips one run takes (Contact/Values): each is at least one
  /// full contact solve.
  constexpr unsigned int max_nips_per_run = 1000;
} // namespace rollnip

#endif
