#ifndef rollnip_changed_entries_h
#define rollnip_changed_entries_h

#include <deal.II/base/parameter_handler.h>

#include <rollnip/global.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rollnip
{
  /**
   * The entries a parameter file gives with a value other than their
   * default (compared as numbers where both are numbers: "8.0" is "8"). An
   * entry written with its default value does not count: a file made by
   * --print-parameters gives every entry. ParameterHandler does not say
   * which entries a file set, so every declared entry gets an action that
   * records its value under its full path ("Mating roll/Geometry/Roll
   * diameter") when the file sets it. Construct after the declarations,
   * before parse_input().
   */
  class ChangedEntries
  {
  public:
    explicit ChangedEntries(ParameterHandler &prm);

    /// Whether the file gave the entry of full path @p path a value other
    /// than its default.
    bool
    changed(const std::string &path) const;

    /// The changed entries whose full path begins with @p prefix (e.g.
    /// "Load/"), except those in @p except, in declaration order.
    std::vector<std::string>
    changed_under(const std::string              &prefix,
                  const std::vector<std::string> &except = {}) const;

  private:
    /// Every declared entry's full path, in declaration order.
    std::vector<std::string> declared;
    /// The declared default of every entry, by full path.
    std::map<std::string, std::string> defaults;
    /// The values the file gave, by full path; shared with the actions.
    std::shared_ptr<std::map<std::string, std::string>> given;
  };
} // namespace rollnip

#endif
