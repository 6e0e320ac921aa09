#ifndef rollnip_ignored_entries_h
#define rollnip_ignored_entries_h

#include <rollnip/changed_entries.h>
#include <rollnip/parameters.h>

#include <string>
#include <vector>

namespace rollnip
{
  /**
   * The entries a file changes (ChangedEntries) that a switch makes
   * irrelevant, one line per switch, naming it and every such entry by
   * its full path:
   * covered-roll entries under Mating roll/ while Mating roll/Type =
   * rigid, Load entries in a contact scene, Contact entries while
   * Contact/Mode = none, and, for each roll, the builtin mesh's entries
   * with a gmsh mesh or the mesh file with the builtin one. Each line is
   * what follows "rollnip: warning: "; none if nothing is ignored.
   */
  std::vector<std::string>
  ignored_entries(const Parameters::AllParameters &parameters,
                  const ChangedEntries            &changed);

  /// Prints ignored_entries() on rank 0 of MPI_COMM_WORLD as
  /// "rollnip: warning: ..." lines on standard error.
  void
  warn_ignored_entries(const Parameters::AllParameters &parameters,
                       const ChangedEntries            &changed);
} // namespace rollnip

#endif
