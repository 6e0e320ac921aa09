#ifndef rollnip_face_crown_h
#define rollnip_face_crown_h

#include <rollnip/face/beam.h>
#include <rollnip/face/face_parameters.h>

#include <functional>
#include <string>

/**
 * Crowns: the change of a roll's radius along the face [mm], zero at the
 * face ends and positive where the roll is fatter (doc/face.md).
 */
namespace rollnip
{
  namespace Face
  {
    using Crown = std::function<double(double)>;

    /// The crown of @p parameters (any shape but ideal) on a face of
    /// length @p face_length, as a radius change.
    Crown
    make_crown(const Parameters::FaceCrown &parameters,
               const double                 face_length);

    /**
     * The ideal crown of a beam: its deflection @p w (nodal, on @p mesh)
     * under the design load, minus its value at the face end, so that
     * the crown makes up for the bending exactly at that load.
     */
    Crown
    ideal_crown(const FaceMesh        &mesh,
                const BeamSection     &section,
                const Eigen::VectorXd &w,
                const double           face_length);

    /// Reads (y, change) rows of a CSV crown table, mirrored if all y >=
    /// 0; throws naming @p entry on a bad file.
    std::vector<std::pair<double, double>>
    read_crown_table(const std::string &file, const std::string &entry);
  } // namespace Face
} // namespace rollnip

#endif
