#ifndef rollnip_app_nip_study_h
#define rollnip_app_nip_study_h

#include <rollnip/contact/inverse_contact.h>
#include <rollnip/contact/nip_control.h>
#include <rollnip/parameters.h>
#include <rollnip/postprocess/error_estimate.h>
#include <rollnip/problem.h>
#include <rollnip/rolling/rolling_numbers.h>

#include <memory>
#include <string>
#include <vector>

namespace rollnip
{
  namespace Parameters
  {
    struct Rolling;
  }

  /// One row of the nip characteristic (nip_characteristic.csv).
  struct NipRow
  {
    ContactResult nonlinear;
    ContactResult linear; ///< same theta0, linear theory (if asked)
    double        max_principal_strain = 0;
    double        bond_sigma_rr_min = 0, bond_sigma_rtheta_max = 0; ///< [MPa]
    double        load_from_traction = 0; ///< P from -sigma_nn on the surface
    double        hertz_load         = 0; ///< Hertz P for the same half-chord
    double        thin_layer_load = 0; ///< thin-layer P for the same half-chord
    /// Hertz's and the thin layer's half-chords at the same P [mm].
    double                  hertz_half_chord = 0, thin_layer_half_chord = 0;
    types::global_dof_index n_dofs  = 0; ///< of the nonlinear problem
    unsigned int            n_cells = 0;
    ErrorEstimate           error;   ///< of the nonlinear nip's numbers
    RollingNumbers          rolling; ///< the rolling loss (if asked)
  };

  /**
   * Mesh levels below a run's own, solved nip by nip ahead of it for an
   * extrapolation (run_nip_study()): the coarsest from its own last nip,
   * as a sweep, each finer level from the same nip of the level below,
   * carried over to its mesh, and the run's level from the finest of
   * them. The caller sets the levels and directories; the run fills the
   * rest.
   */
  struct CoarserLevels
  {
    std::vector<unsigned int>        levels; ///< ascending, below the run's
    std::vector<std::string>         directories; ///< each level's files
    std::vector<std::vector<NipRow>> rows;    ///< each level's converged nips
    std::vector<double>              seconds; ///< each level's wall time [s]
  };

  /// The numbers of @p row that carry an error estimate.
  NipNumbers
  nip_numbers(const NipRow &row);

  /**
   * Runs the contact scenes of the Contact subsection (doc/intro.md,
   * section 7): for each of Contact/Values, the nip controlled by theta0,
   * P or u0; writes each nip's files (in the output directory for one
   * value, in nip-NN/ below it for a sweep), the nip characteristic with
   * linear theory, Hertz and the thin-layer asymptote beside it, and
   * prints the table, on the processes of @p communicator. With
   * @p rolling enabled, each nip also gets its rolling loss and cover
   * temperature (doc/rolling.md). Returns the exit code; the rows, if
   * @p rows_out is given, go there too. With @p guard_rails, nips outside
   * the validated range of the material law are warned about
   * (warn_outside_validated_range()); a sweep that is raw material for
   * another model (the face's cross-section law) has none. With
   * @p coarser, its levels solve each nip first, and each level's nip
   * characteristic goes to its directory.
   */
  int
  run_nip_study(const Parameters::AllParameters &parameters,
                MPI_Comm                         communicator,
                std::vector<NipRow>             *rows_out    = nullptr,
                const Parameters::Rolling       *rolling     = nullptr,
                bool                             guard_rails = true,
                CoarserLevels                   *coarser     = nullptr);

} // namespace rollnip

#endif
