#ifndef rollnip_app_accuracy_target_h
#define rollnip_app_accuracy_target_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <rollnip/parameters.h>
#include <rollnip/postprocess/error_estimate.h>

#include <string>
#include <vector>

namespace rollnip
{
  namespace Parameters
  {
    /// Accuracy/Target and Accuracy/Target quantities: the relative error
    /// a contact run must reach, and the numbers it applies to
    /// (doc/accuracy.md, "An accuracy target").
    struct AccuracyTarget
    {
      /// Relative error, e.g. 1e-3 for "0.1 %"; 0: off (the mesh and
      /// element of the file are used as they are).
      double                          target = 0;
      std::vector<NipQuantity::Index> quantities;

      /// Declares the two entries in subsection Accuracy.
      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
      /// With a target: checks it against the rest of the scene @p scene.
      void
      check(const AllParameters &scene) const;
    };
  } // namespace Parameters

  /// One (element, level) the accuracy target may choose.
  struct AccuracyCandidate
  {
    Parameters::Element element;
    unsigned int        level;
    /// relative: DoFs of the run's roll plus those of its error
    /// estimate's companion, weighted by its measured relative cost
    double cost;
    /// Solved on the halved coarse mesh (halve_coarse_mesh()) rather
    /// than the file's: one refinement of it is the file's level-0 mesh
    /// with more nip cells, and its error estimate's companion is then
    /// the cheap coarse level instead of the finer one.
    bool halved_mesh = false;
    /// With theta0 prescribed only: the answer is extrapolated at order 1
    /// from this level and the one below, and its error estimated from
    /// the level below that (extrapolate_first_order()); the three levels
    /// are solved without the error estimate's companion.
    bool extrapolated = false;
    /// Halvings of the cells about the contact edge beyond the level
    /// (Mesh/Edge refinements, on the nip-fitted mesh).
    unsigned int edge_refinements = 0;
  };

  /**
   * The coarse mesh of the halved-mesh candidates: half the radial cells
   * and half the circumferential cells beyond the nip (rounded up, at
   * least two beyond the nip), and 5/6 of the nip cells (at least two).
   * Refined once it has the file's radial cells and cells beyond the nip
   * and 5/3 of its nip cells: on the default scene 4 x 11 coarse cells,
   * 5 in the nip, whose level 1 has 8 x 22 cells, 10 in the nip, where the
   * file's level 0 has 8 x 18 with 6 (doc/accuracy.md, "An accuracy
   * target").
   */
  void
  halve_coarse_mesh(Parameters::Mesh &mesh);

  /// The candidates, cheapest first: Q1-P0 at levels 0 to 4, Q2-P1 at
  /// levels 0 to 3 with and without the cells about the contact edge
  /// refined further (the former for P or u0 prescribed: b converges from
  /// an error 20 times smaller) and Q2-P1 on the halved coarse mesh at
  /// levels 1 to 3,
  /// ordered by the DoFs on the builtin mesh of the run
  /// and of its error estimate's companion (Q2-P1 has about 3.5 times the
  /// DoFs of Q1-P0 at the same level; the companion of a level-0 run is
  /// the finer level 1, so Q1-P0 at level 1 costs about as much as at
  /// level 0); and, for theta0 prescribed, the extrapolated Q1-P0 at
  /// levels 2 to 5, Q2-P1 at levels 2 to 4 and Q2-P1 on the halved coarse
  /// mesh at levels 2 and 3, the last two with the cells about the contact
  /// edge refined further, which cost the DoFs of their three levels.
  std::vector<AccuracyCandidate>
  accuracy_candidates();

  /// The predicted largest relative error of quantity @p q of the default
  /// scene's nips for @p candidate under @p mode, from the measured
  /// level-0 errors and the orders of error_order() (doc/accuracy.md);
  /// infinite for an extrapolated candidate unless theta0 is prescribed,
  /// and for an edge-refined one that is not extrapolated if it is.
  double
  predicted_error(const AccuracyCandidate      &candidate,
                  const NipQuantity::Index      q,
                  const Parameters::ContactMode mode);

  /**
   * The contact run of @p parameters to the accuracy @p target: solves the
   * sweep with its error estimate at the cheapest (element, level) the
   * cost model predicts to meet it, calibrates the model on each estimate
   * and moves to the next cheaper-predicted candidate until every nip's
   * estimated error of each target quantity is within the target. The
   * results files are those of the chosen run; accuracy_target.csv lists
   * every candidate tried. Returns the exit code: 1 (said) if no candidate
   * met the target or a run failed.
   */
  int
  run_to_accuracy_target(const Parameters::AllParameters  &parameters,
                         const Parameters::AccuracyTarget &target,
                         MPI_Comm                          communicator);
} // namespace rollnip

#endif
