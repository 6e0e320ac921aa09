#ifndef rollnip_parameter_entries_h
#define rollnip_parameter_entries_h

#include <deal.II/base/parameter_handler.h>

#include <rollnip/global.h>

#include <string>

/**
 * Helpers of the .prm declarations and their messages, shared by
 * parameters.cc and engineering_inputs.cc (implemented in parameters.cc).
 */
namespace rollnip
{
  namespace Parameters
  {
    /// Declares an entry whose documentation ends with its allowed values,
    /// so that --print-parameters shows the range of every entry.
    void
    declare_documented(ParameterHandler            &prm,
                       const std::string           &name,
                       const std::string           &default_value,
                       const Patterns::PatternBase &pattern,
                       const std::string           &doc);

    /// A value for a message, in the shortest form (1e+300, not 300
    /// digits).
    std::string
    number(const double x);

    /// @p message with every entry of a roll's subsection it names
    /// ("Geometry/Cover thickness", "Material:") put under @p prefix
    /// ("Mating roll/"): for messages of the code that reads both rolls.
    std::string
    with_entry_prefix(const std::string &message, const std::string &prefix);
  } // namespace Parameters
} // namespace rollnip

#endif
