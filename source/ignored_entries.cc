#include <deal.II/base/mpi.h>

#include <rollnip/ignored_entries.h>
#include <rollnip/parameter_entries.h>

#include <cmath>
#include <iostream>

namespace rollnip
{
  namespace
  {
    /// "A, B and C".
    std::string
    listed(const std::vector<std::string> &names)
    {
      std::string s;
      for (std::size_t i = 0; i < names.size(); ++i)
        s += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
      return s;
    }

    /// The line for @p names, ignored because of @p why (a switch and its
    /// value), with the @p reason and the @p advice ("them" in it becomes
    /// "it" for a single entry).
    void
    add(std::vector<std::string>       &lines,
        const std::vector<std::string> &names,
        const std::string              &why,
        const std::string              &reason,
        std::string                     advice)
    {
      if (names.empty())
        return;
      const std::size_t them = advice.find("them");
      if (names.size() == 1 && them != std::string::npos)
        advice.replace(them, 4, "it");
      lines.push_back(why + ": " + listed(names) +
                      (names.size() == 1 ? " is" : " are") + " ignored (" +
                      reason + "): " + advice);
    }

    std::string
    mode_name(const Parameters::ContactMode mode)
    {
      switch (mode)
        {
          case Parameters::ContactMode::nip_angle:
            return "nip angle";
          case Parameters::ContactMode::load:
            return "load";
          case Parameters::ContactMode::indentation:
            return "indentation";
          default:
            return "none";
        }
    }

    /// The mesh entries of one roll (@p prefix "" or "Mating roll/") that
    /// its Mesh/Source does not read.
    void
    add_mesh_source(std::vector<std::string> &lines,
                    const Parameters::Mesh   &mesh,
                    const std::string        &prefix,
                    const ChangedEntries     &changed)
    {
      const std::string m = prefix + "Mesh/";
      if (mesh.source == Parameters::MeshSource::builtin)
        add(lines,
            changed.changed(m + "Mesh file")
              ? std::vector<std::string>{m + "Mesh file"}
              : std::vector<std::string>{},
            m + "Source = builtin",
            "the builtin mesh is used",
            "set " + m + "Source = gmsh to read the file, or remove them");
      else
        {
          std::vector<std::string> builtin;
          for (const char *name : {"Radial cells",
                                   "Circumferential cells",
                                   "Circumferential grading",
                                   "Radial grading",
                                   "Nip cells",
                                   "Nip grading",
                                   "Edge refinements"})
            if (changed.changed(m + name))
              builtin.push_back(m + name);
          add(lines,
              builtin,
              m + "Source = gmsh",
              "the cells are those of " + m + "Mesh file",
              "remove them, or set " + m + "Source = builtin");
        }
    }
  } // namespace

  std::vector<std::string>
  ignored_entries(const Parameters::AllParameters &p,
                  const ChangedEntries            &changed)
  {
    std::vector<std::string> lines;
    if (!p.mating_roll.covered)
      add(lines,
          changed.changed_under("Mating roll/", {"Mating roll/Type"}),
          "Mating roll/Type = rigid",
          "the mating roll is " +
            (std::isinf(p.contact.indenter_radius)
               ? std::string("the rigid plane of Contact/Indenter radius = inf")
               : "the rigid circle of Contact/Indenter radius = " +
                   Parameters::number(p.contact.indenter_radius) + " mm"),
          "set Mating roll/Type = covered roll, or remove them");
    if (p.contact.mode != Parameters::ContactMode::none)
      add(lines,
          changed.changed_under("Load/"),
          "Contact/Mode = " + mode_name(p.contact.mode),
          "a contact scene finds its own pressure",
          "remove them, or set Contact/Mode = none to apply Load/Pressure "
          "function");
    else
      add(lines,
          changed.changed_under("Contact/", {"Contact/Mode"}),
          "Contact/Mode = none",
          "a pressure scene applies Load/Pressure function",
          "set Contact/Mode to nip angle, load or indentation, or remove "
          "them");
    add_mesh_source(lines, p.mesh, "", changed);
    if (p.mating_roll.covered)
      add_mesh_source(lines, p.mating_roll.mesh, "Mating roll/", changed);
    return lines;
  }

  void
  warn_ignored_entries(const Parameters::AllParameters &parameters,
                       const ChangedEntries            &changed)
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    for (const std::string &line : ignored_entries(parameters, changed))
      std::cerr << "rollnip: warning: " << line << std::endl;
  }
} // namespace rollnip
