#ifndef rollnip_app_cross_section_law_h
#define rollnip_app_cross_section_law_h

#include <deal.II/base/mpi.h>

#include <rollnip/face/face_parameters.h>
#include <rollnip/parameters.h>

#include <string>
#include <vector>

/**
 * The foundation of the face model from the scene's own cross-section
 * (doc/face.md): rollnip's nip sweep in indentation mode over the
 * approaches the face needs, kept in a CSV file whose name holds a hash
 * of the cross-section's parameters and reused while they are unchanged.
 */
namespace rollnip
{
  namespace Face
  {
    /// The sampled law: one row per approach.
    struct LawSamples
    {
      std::vector<double> approach;      ///< u0 [mm]
      std::vector<double> line_load;     ///< P_2D [N/mm]
      std::vector<double> half_width;    ///< b [mm]
      std::vector<double> peak_pressure; ///< [MPa]
      std::string         file;          ///< the cache file
      bool                from_cache    = false;
      double              sweep_seconds = 0; ///< of the sweep that made it
      unsigned int        n_cells       = 0;
    };

    /// The approaches of the sweep: Face/Law samples, geometric from
    /// the largest approach over Face/Law range to the largest, which is
    /// Face/Law maximum approach or estimated for @p line_load [N/mm].
    std::vector<double>
    law_approaches(const Parameters::AllParameters &parameters,
                   const Parameters::Face          &face,
                   const double                     line_load);

    /// The text that identifies the cross-section and the sweep: every
    /// parameter the law depends on (not Face or Output).
    std::string
    cross_section_key(const Parameters::AllParameters &parameters,
                      const std::vector<double>       &approaches);

    /// The law at @p approaches: read from the cache file if it holds
    /// this cross-section's, else swept on the processes of
    /// @p communicator (collective) and written there.
    LawSamples
    cross_section_law(const Parameters::AllParameters &parameters,
                      const Parameters::Face          &face,
                      const std::vector<double>       &approaches,
                      MPI_Comm                         communicator);
  } // namespace Face
} // namespace rollnip

#endif
