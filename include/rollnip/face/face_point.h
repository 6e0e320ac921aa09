#ifndef rollnip_face_face_point_h
#define rollnip_face_face_point_h

#include <rollnip/face/beam.h>
#include <rollnip/face/face_solver.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <array>
#include <vector>

namespace rollnip
{
  namespace Face
  {
    /// The points per face element where the foundation is integrated
    /// (Gauss on [0, 1]).
    constexpr unsigned int n_face_points = 3;

    /// Point @p g of the Gauss rule on [0, 1] and its weight.
    double
    face_gauss_point(const unsigned int g);
    double
    face_gauss_weight(const unsigned int g);

    /// A point of the face where the foundation acts: its beam element,
    /// position y [mm], weight [mm], crown [mm] and both beams' deflection
    /// shape functions there.
    struct FacePoint
    {
      unsigned int          element;
      double                y, weight, crown;
      std::array<double, 4> roll, mate;
    };

    /// Point @p g of the face element starting at node @p e of @p mesh.
    FacePoint
    face_point(const FaceModel   &model,
               const FaceMesh    &mesh,
               const unsigned int e,
               const unsigned int g);

    /// The local approach delta = a - w_roll - w_mate + crown at @p p for
    /// the unknowns @p x: the roll's beam from entry 0, the mating roll's
    /// (if @p with_mate) from @p n_roll, the bearing approach a at
    /// @p approach.
    double
    local_approach(const Eigen::VectorXd &x,
                   const FacePoint       &p,
                   const unsigned int     approach,
                   const unsigned int     n_roll,
                   const bool             with_mate);

    /// Finishes the Newton system of a face problem with @p n unknowns:
    /// zeroes the @p residual at the supported unknowns @p supports and, if
    /// @p tangent is given, assembles it from the state-dependent
    /// @p entries and the constant @p fixed ones without the supported rows
    /// and columns, with 1 on their diagonal.
    void
    apply_supports(const std::vector<unsigned int>           &supports,
                   const std::vector<Eigen::Triplet<double>> &fixed,
                   std::vector<Eigen::Triplet<double>>        entries,
                   const unsigned int                         n,
                   Eigen::VectorXd                           &residual,
                   Eigen::SparseMatrix<double>               *tangent);
  } // namespace Face
} // namespace rollnip

#endif
