#include <rollnip/changed_entries.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <set>
#include <sstream>

namespace rollnip
{
  namespace
  {
    /// What @p prm declares, read from its short .prm listing
    /// ("subsection NAME", "set NAME = VALUE", "end") before any file is
    /// parsed: the full paths of its entries in declaration order, their
    /// defaults, and the full paths of its subsections.
    void
    read_declarations(const ParameterHandler             &prm,
                      std::vector<std::string>           &entries,
                      std::map<std::string, std::string> &defaults,
                      std::set<std::string>              &sections)
    {
      std::ostringstream listing;
      prm.print_parameters(listing,
                           ParameterHandler::ShortPRM |
                             ParameterHandler::KeepDeclarationOrder);
      std::istringstream in(listing.str());
      std::string        line, path; // path: the open subsections, "A/B/"
      while (std::getline(in, line))
        {
          const std::size_t start = line.find_first_not_of(' ');
          if (start == std::string::npos)
            continue;
          line = line.substr(start);
          if (line.rfind("subsection ", 0) == 0)
            {
              path += line.substr(11);
              sections.insert(path);
              path += '/';
            }
          else if (line == "end" && !path.empty())
            {
              path.pop_back();
              const std::size_t slash = path.find_last_of('/');
              path.erase(slash == std::string::npos ? 0 : slash + 1);
            }
          else if (line.rfind("set ", 0) == 0)
            {
              const std::size_t equals = line.find(" = ");
              std::string       name   = line.substr(4, equals - 4);
              name.erase(name.find_last_not_of(' ') + 1);
              entries.push_back(path + name);
              defaults[entries.back()] = equals == std::string::npos
                                           ? std::string()
                                           : line.substr(equals + 3);
            }
        }
    }

    /// @p path split into its subsections and the entry name. An entry
    /// name may hold a '/' itself ("C2/C1 ratio"): a part is a subsection
    /// only if @p sections has it.
    std::vector<std::string>
    split_path(const std::string &path, const std::set<std::string> &sections)
    {
      std::vector<std::string> parts;
      std::size_t              begin = 0;
      for (std::size_t slash = path.find('/'); slash != std::string::npos;
           slash             = path.find('/', slash + 1))
        if (sections.count(path.substr(0, slash)))
          {
                        parts.push_back(path.substr(begin, slash - begin));
                        begin = slash + 1;
          }
      parts.push_back(path.substr(begin));
      return parts;
    }

    /// @p text as a number if all of it is one, else NaN.
    double
    whole_number(const std::string &text)
    {
      char        *end   = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      return !text.empty() && end == text.c_str() + text.size()
               ? value
               : std::numeric_limits<double>::quiet_NaN();
    }
  } // namespace

  ChangedEntries::ChangedEntries(ParameterHandler &prm)
      : given(std::make_shared<std::map<std::string, std::string>>())
  {
    std::set<std::string> sections;
    read_declarations(prm, declared, defaults, sections);
    for (const std::string &path : declared)
      {
        const std::vector<std::string> parts = split_path(path, sections);
        for (std::size_t i = 0; i + 1 < parts.size(); ++i)
          prm.enter_subsection(parts[i]);
        const auto record = given;
        prm.add_action(parts.back(), [record, path](const std::string &value) {
          (*record)[path] = value;
        });
        for (std::size_t i = 0; i + 1 < parts.size(); ++i)
          prm.leave_subsection();
      }
    // add_action() has run each action once, on the default value.
    given->clear();
  }

  bool
  ChangedEntries::changed(const std::string &path) const
  {
    const auto value = given->find(path);
    if (value == given->end())
      return false;
    const auto         declared_default = defaults.find(path);
    const std::string  fallback;
    const std::string &d =
      declared_default == defaults.end() ? fallback : declared_default->second;
    if (value->second == d)
      return false;
    const double a = whole_number(value->second), b = whole_number(d);
    return !(a == b); // NaN (not both numbers) compares unequal
  }

  std::vector<std::string>
  ChangedEntries::changed_under(const std::string              &prefix,
                                const std::vector<std::string> &except) const
  {
    std::vector<std::string> found;
    for (const std::string &path : declared)
      if (path.rfind(prefix, 0) == 0 && changed(path) &&
          std::find(except.begin(), except.end(), path) == except.end())
        found.push_back(path);
    return found;
  }
} // namespace rollnip
