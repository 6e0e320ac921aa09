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
  } // namespace

  void
  check_cost(const Parameters::AllParameters &parameters,
             const double                     coarse_cells)
  {
    // The iterative solver's memory was not measured: it is not checked.
    if (parameters.linear_solver.method == "gmres-amg")
      return;
    // A study sets Global refinements to each of its levels.
    unsigned int level =
      parameters.study.levels.empty() ? parameters.mesh.global_refinements : 0;
    for (const unsigned int l : parameters.study.levels)
      level = std::max(level, l);
    Parameters::Element element = parameters.discretization.element;
    for (const Parameters::Element e : parameters.study.elements)
      if (e == Parameters::Element::q2_p1)
        element = e;
    const double cells  = coarse_cells * std::pow(4., level);
    const double dofs   = cells * dofs_per_cell(element);
    const double memory = dofs * bytes_per_dof(element);
    const double have   = physical_memory();
    if (have > 0 && memory > have)
      {
        std::ostringstream s;
        s.precision(3);
        s << "Mesh/Global refinements (or Study/Refinement levels) = " << level
          << " gives about " << cells << " cells and " << dofs
          << " DoFs; the direct solver would need about " << memory / 1e9
          << " GB, more than this machine's " << have / 1e9
          << " GB: use fewer refinements";
        AssertThrow(false, ExcMessage(s.str()));
      }
  }
} // namespace rollnip
