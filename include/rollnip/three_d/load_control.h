#ifndef rollnip_three_d_load_control_h
#define rollnip_three_d_load_control_h

#include <rollnip/three_d/slice_body.h>

namespace rollnip
{
  namespace three_d
  {
    /**
     * Load control (Contact/Mode = load): the approach u0 at which @p body
     * carries the line load @p target [N/mm], found by a secant iteration
     * on the local power law P ~ u0^n through the last two solves (n from
     * them, 1.5 at the start: a Hertz-like nip), kept inside the bracket
     * once both sides are known, each solve started from the body's last
     * state. @p previous is the last converged nip (u0 = P = 0 before the
     * first); @p first_approach the first trial when there is none. Stops
     * when |P - target| <= @p tolerance target; throws after
     * @p max_iterations solves. The nip returned counts the Newton steps
     * and GMRES iterations of all its solves.
     */
    SliceNip
    solve_for_load(SliceBody         &body,
                   const double       target,
                   const SliceNip    &previous,
                   const double       first_approach,
                   const double       tolerance,
                   const unsigned int max_iterations);
  } // namespace three_d
} // namespace rollnip

#endif
