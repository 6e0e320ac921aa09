#ifndef rollnip_body_nested_transfer_h
#define rollnip_body_nested_transfer_h

#include <rollnip/body/roll_body.h>

namespace rollnip
{
  /**
   * The displacement of @p from as the state of @p to, where both meshes
   * are global refinements of the same coarse mesh (the same scene at two
   * mesh levels, or with two elements): every displacement node of @p to
   * takes the value of @p from's field at the same logical point of the
   * coarse cell. The pressure unknowns of @p to are set to zero (one
   * Newton step restores them: the residual is linear in them). It starts
   * the error estimate's companion from the answer instead of from an
   * unloaded cover. Returns false, and leaves @p to as it was, where it
   * cannot map the meshes onto each other (several processes, or another
   * coarse mesh).
   */
  bool
  transfer_nested_displacement(const RollBody &from, RollBody &to);
} // namespace rollnip

#endif
