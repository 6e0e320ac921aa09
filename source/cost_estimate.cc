#include <deal.II/base/exceptions.h>

#include <rollnip/cost_estimate.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rollnip
{
  namespace
  {
    /// DoFs per cell of a large mesh: Q1-P0 has about one vertex (2
    /// displacement DoFs) and one pressure per cell, Q2-P1 four nodes and
    /// three pressures.
    double
    dofs_per_cell(const Parameters::Element element)
    {
      return element == Parameters::Element::q2_p1 ? 11. : 3.;
    }

    /// Bytes per DoF of the factorised Newton matrix and the vectors, an
    /// upper value of the measurements (3.7 kB at 1e5 DoFs, Q1-P0);
    /// Q2-P1's denser rows are taken at twice that.
    double
    bytes_per_dof(const Parameters::Element element)
    {
      return (element == Parameters::Element::q2_p1 ? 2. : 1.) * 3.7e3;
    }

    double
    physical_memory()
    {
      const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
      return pages > 0 && size > 0 ? double(pages) * double(size) : 0.;
    }

    /// The finest level a run of @p parameters refines its roll to: a
    /// study sets Global refinements to each of its levels.
    unsigned int
    finest_level(const Parameters::AllParameters &parameters)
    {
      unsigned int level = parameters.study.levels.empty()
                             ? parameters.mesh.global_refinements
                             : 0;
      for (const unsigned int l : parameters.study.levels)
        level = std::max(level, l);
      return level;
    }

    /// Refuses the roll of @p cost, whose refinements are the entry
    /// @p entry, when @p total bytes (with the other roll's) exceed the
    /// machine's.
    void
    refuse_if_too_large(const CostEstimate &cost,
                        const std::string  &entry,
                        const double        total)
    {
      const double have = physical_memory();
      if (!(have > 0 && total > have))
        return;
      std::ostringstream s;
      s.precision(3);
      s << entry << " = " << cost.level << " gives about " << cost.cells
        << " cells and " << cost.dofs
        << " DoFs; the direct solver would need about " << cost.memory / 1e9
        << " GB";
      if (total > 1.01 * cost.memory)
        s << " (" << total / 1e9 << " GB with the other roll)";
      s << ", more than this machine's " << have / 1e9
        << " GB: use fewer refinements";
      AssertThrow(false, ExcMessage(s.str()));
    }
  } // namespace

  CostEstimate
  estimate_cost(const Parameters::AllParameters &parameters,
                const double                     coarse_cells,
                const unsigned int               level)
  {
    Parameters::Element element = parameters.discretization.element;
    for (const Parameters::Element e : parameters.study.elements)
      if (e == Parameters::Element::q2_p1)
        element = e;
    CostEstimate cost;
    cost.level  = level;
    cost.cells  = coarse_cells * std::pow(4., level);
    cost.dofs   = cost.cells * dofs_per_cell(element);
    cost.memory = cost.dofs * bytes_per_dof(element);
    return cost;
  }

  void
  check_cost(const Parameters::AllParameters &parameters,
             const double                     coarse_cells)
  {
    // The iterative solver's memory was not measured: it is not checked.
    if (parameters.linear_solver.method == "gmres-amg")
      return;
    const CostEstimate cost =
      estimate_cost(parameters, coarse_cells, finest_level(parameters));
    refuse_if_too_large(cost,
                        "Mesh/Global refinements (or Study/Refinement levels)",
                        cost.memory);
  }

  void
  check_cost(const Parameters::AllParameters &parameters,
             const double                     coarse_cells,
             const double                     mate_coarse_cells)
  {
    if (parameters.linear_solver.method == "gmres-amg")
      return;
    const CostEstimate roll =
      estimate_cost(parameters, coarse_cells, finest_level(parameters));
    const CostEstimate mate =
      estimate_cost(parameters,
                    mate_coarse_cells,
                    parameters.mating_roll.mesh.global_refinements);
    const double total = roll.memory + mate.memory;
    if (mate.memory > roll.memory)
      refuse_if_too_large(mate, "Mating roll/Mesh/Global refinements", total);
    else
      refuse_if_too_large(
        roll, "Mesh/Global refinements (or Study/Refinement levels)", total);
  }
} // namespace rollnip
