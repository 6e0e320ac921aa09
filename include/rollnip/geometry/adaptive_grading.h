#ifndef rollnip_geometry_adaptive_grading_h
#define rollnip_geometry_adaptive_grading_h

#include <rollnip/parameters.h>

#include <vector>

namespace rollnip
{
  class RollProblem;

  /**
   * New coarse circumferential cell widths [rad] for the solved state of
   * @p problem, whose coarse widths were @p steps: r-adaptivity, no
   * hanging nodes. The Kelly indicator eta_K (jumps of the displacement
   * gradient) is summed per coarse column j into E_j. With the error of a
   * column modelled as E = rho w^(2p+1) (p the displacement degree, w the
   * width), the error density rho = E_j / w_j^(2p+1) is piecewise
   * constant in theta, and the widths minimising the total error for the
   * same number of cells have the density 1/w ~ rho^(1/(2p+1)). The
   * density is limited to change by 1.5 between neighbours, and the new
   * vertices equidistribute it.
   */
  std::vector<double>
  adapted_circumferential_steps(const RollProblem         &problem,
                                const std::vector<double> &steps,
                                const double               sector_angle);
} // namespace rollnip

#endif
