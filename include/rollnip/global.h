#ifndef rollnip_global_h
#define rollnip_global_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

/**
 * Everything of rollnip lives in this namespace. deal.II's names are pulled
 * in here, and only here, so that headers of other projects stay untouched.
 */
namespace rollnip
{
  using namespace dealii;

  /// The problem is plane strain: every mesh and FE object is two-dimensional.
  constexpr unsigned int dim = 2;
} // namespace rollnip

#endif
