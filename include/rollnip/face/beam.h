#ifndef rollnip_face_beam_h
#define rollnip_face_beam_h

#include <rollnip/face/face_parameters.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <array>
#include <vector>

/**
 * The cores of the face model as beams along the face coordinate y
 * (doc/face.md): two-node Timoshenko elements with the exact
 * interpolation of a prismatic beam, so that nodal deflections under nodal
 * loads are exact, and the Euler-Bernoulli element as their limit.
 */
namespace rollnip
{
  namespace Face
  {
    /// What a core's beam needs of its cross-section.
    struct BeamSection
    {
      double bending_stiffness; ///< EI [N mm^2]
      /// kappa G A [N]; 0 means rigid in shear (Euler-Bernoulli).
      double shear_stiffness = 0;
      double weight          = 0; ///< own weight per length [N/mm]
    };

    /// EI, kappa G A (Cowper's kappa of a thick tube) and the weight of
    /// @p core; without @p shear the beam is Euler-Bernoulli.
    BeamSection
    tube_section(const Parameters::FaceCore &core, const bool shear);

    /**
     * The nodes along y: the bearings at +-B/2, the face ends at +-L/2
     * and, between them, elements about L / n long. Every element lies
     * either on the face or on a journal.
     */
    struct FaceMesh
    {
      std::vector<double> y;
      /// Nodes at the face ends: the face is [first_face_node,
      /// last_face_node].
      unsigned int first_face_node, last_face_node;

      FaceMesh(const double       face_length,
               const double       bearing_distance,
               const unsigned int face_elements);

      unsigned int
      n_nodes() const
      {
        return y.size();
      }
      /// Whether element e (nodes e, e + 1) is on the face.
      bool
      on_face(const unsigned int e) const
      {
        return e >= first_face_node && e < last_face_node;
      }
      /// The element holding @p y0 (the face's first at its left end).
      unsigned int
      element_at(const double y0) const;
    };

    /// Stiffness of the element of length @p h, dofs (w1, theta1, w2,
    /// theta2) with theta = w' for Euler-Bernoulli.
    Eigen::Matrix4d
    element_stiffness(const BeamSection &section, const double h);

    /// phi = 12 EI / (kappa G A h^2) of an element of length @p h.
    double
    shear_ratio(const BeamSection &section, const double h);

    /// The element's deflection shape functions at @p xi in [0, 1], w =
    /// sum N_i u_i over (w1, theta1, w2, theta2): those of the exact
    /// Timoshenko element, the Hermite cubics at @p phi = 0.
    std::array<double, 4>
    deflection_shape(const double xi, const double h, const double phi);

    /// The deflection of the nodal vector @p u (dofs 2 i, 2 i + 1 at node
    /// i) at @p y0, interpolated by deflection_shape().
    double
    deflection_at(const FaceMesh        &mesh,
                  const BeamSection     &section,
                  const Eigen::VectorXd &u,
                  const double           y0);

    /// Adds the stiffness of a beam on @p mesh (dofs from @p offset) to
    /// @p entries and the nodal forces of the line load @p load [N/mm]
    /// along the whole beam to @p forces.
    void
    add_beam_matrix(const FaceMesh                      &mesh,
                    const BeamSection                   &section,
                    const double                         load,
                    const unsigned int                   offset,
                    std::vector<Eigen::Triplet<double>> &entries,
                    Eigen::VectorXd                     &forces);

    /**
     * Nodal deflections of a beam simply supported at the mesh's first and
     * last node under the line load @p face_load [N/mm] on the face and
     * @p beam_load [N/mm] along the whole beam (positive along w).
     */
    Eigen::VectorXd
    simply_supported_deflection(const FaceMesh    &mesh,
                                const BeamSection &section,
                                const double       face_load,
                                const double       beam_load);
  } // namespace Face
} // namespace rollnip

#endif
