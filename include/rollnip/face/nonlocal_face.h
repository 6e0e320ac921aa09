#ifndef rollnip_face_nonlocal_face_h
#define rollnip_face_nonlocal_face_h

#include <rollnip/face/face_solver.h>

namespace rollnip
{
  namespace Face
  {
    /**
     * The non-local foundation (doc/face.md, "Cover ends"): the line load
     * q, piecewise linear on the face nodes, solves q - l^2 q'' =
     * P(delta) with q = 0 at the face ends, l = FaceModel::nonlocal_length,
     * in the weak form (mass plus l^2 stiffness of linear elements).
     * Newton on the beams, the approach and q together from the local
     * @p solution, which it overwrites (nodal_line_load then holds q).
     */
    void
    solve_nonlocal(const FaceModel &model, FaceSolution &solution);
  } // namespace Face
} // namespace rollnip

#endif
