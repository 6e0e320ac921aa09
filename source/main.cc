#include <deal.II/base/mpi.h>

#include <rollnip/app/accuracy_target.h>
#include <rollnip/app/adaptive_grading.h>
#include <rollnip/app/face_run.h>
#include <rollnip/app/nip_study.h>
#include <rollnip/app/pressure_run.h>
#include <rollnip/app/quick_nip.h>
#include <rollnip/app/refinement_study.h>
#include <rollnip/app/run_parameters.h>
#include <rollnip/engineering_inputs.h>
#include <rollnip/interrupt.h>
#include <rollnip/mpi_start.h>
#include <rollnip/output/report_stream.h>
#include <rollnip/parameters.h>
#include <rollnip/rolling/rolling_parameters.h>
#include <rollnip/run_errors.h>
#include <rollnip/solvers/tolerance_floor.h>
#include <rollnip/three_d/slice_run.h>

#include <iostream>
#include <memory>
#include <string>

namespace
{
  const char *const usage =
    "Usage: rollnip [options] FILE.prm\n"
    "       rollnip nip --diameter 400 --cover 20 --hardness 70A --mate 300 "
    "--load 40kN/m\n"
    "                   (a nip from its engineering numbers: rollnip nip "
    "--help)\n"
    "\n"
    "Computes the deformation and stresses of a rubber roll cover bonded to a\n"
    "rigid core under a follower pressure (plane strain, incompressible\n"
    "Mooney-Rivlin, Q1-P0 finite elements); see README.md.\n"
    "\n"
    "Options:\n"
    "  -h, --help              this text\n"
    "  --print-parameters      write every parameter with its default, range\n"
    "                          and documentation in .prm form, then exit\n"
    "  --validate              read and check FILE.prm and the mesh, then "
    "exit\n"
    "\n"
    "Run in parallel with: mpirun -np N rollnip FILE.prm\n"
    "Exit status: 0 when the full load was reached, 1 on bad input or when\n"
    "the run stopped early (the last converged state is written).\n";

  /// Reads the command line into @p file and @p validate_only; returns
  /// the exit code when the run ends here (help, an error), else -1.
  int
  parse_arguments(const int    argc,
                  char       **argv,
                  const bool   root,
                  std::string &file,
                  bool        &validate_only)
  {
    using namespace rollnip;
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        if (arg == "-h" || arg == "--help")
          {
            if (root)
              std::cout << usage;
            return 0;
          }
        else if (arg == "--print-parameters")
          {
            if (root)
              {
                ParameterHandler prm;
                Parameters::AllParameters::declare(prm);
                prm.print_parameters(std::cout,
                                     ParameterHandler::PRM |
                                       ParameterHandler::KeepDeclarationOrder);
              }
            return 0;
          }
        else if (arg == "--validate")
          validate_only = true;
        else if (!arg.empty() && arg[0] == '-')
          {
            if (root)
              std::cerr << "rollnip: error: unknown option '" << arg
                        << "' (see rollnip --help)" << std::endl;
            return 1;
          }
        else if (file.empty())
          file = arg;
        else
          {
            if (root)
              std::cerr << "rollnip: error: more than one parameter file given "
                           "(see rollnip --help)"
                        << std::endl;
            return 1;
          }
      }
    if (file.empty())
      {
        if (root)
          std::cerr << "rollnip: error: no parameter file given (see rollnip "
                       "--help)"
                    << std::endl;
        return 1;
      }
    return -1;
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace rollnip;
  // The command line is read before MPI starts: --help, --print-parameters
  // and a wrong argument answer at once (MPI_Init leaves argv as it is).
  std::string file;
  bool        validate_only = false;
  if (const int code =
        is_quick_nip(argc, argv)
          ? prepare_quick_nip(argc, argv, is_launch_root(), file)
          : parse_arguments(argc, argv, is_launch_root(), file, validate_only);
      code >= 0)
    return code;

  prepare_single_process_mpi();
  // Threads fill the cores the MPI processes leave (DEAL_II_NUM_THREADS caps).
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
  // The processes of every run: the application passes them down.
  const MPI_Comm communicator = MPI_COMM_WORLD;
  const bool     root = Utilities::MPI::this_mpi_process(communicator) == 0;

  install_interrupt_handlers();
  return run_guarded(root, [&]() {
    RunParameters run;
    run.read(file);
    auto &parameters = run.scene;
    for (const auto &warning : ToleranceFloor::apply(parameters))
      if (root)
        std::cerr << "rollnip: warning: " << warning << std::endl;
    const auto &face     = run.face;
    const auto &accuracy = run.accuracy;
    const auto &rolling  = run.rolling;
    const auto &three_d  = run.three_d;
    AssertThrow(!rolling.enabled ||
                  (!face.enabled && parameters.study.levels.empty() &&
                   accuracy.target == 0),
                ExcMessage("Rolling/Enabled works on a nip sweep: not with "
                           "Face/Enabled, Study/Refinement levels or "
                           "Accuracy/Target"));
    // Quiet: only the report, warnings and errors reach the screen.
    const QuietRun quiet(parameters.output.verbosity ==
                         Parameters::Verbosity::quiet);
    if (root)
      std::cout << EngineeringInputs::describe(parameters);
    if (face.enabled && !validate_only)
      return run_face(parameters, face, communicator);
    if (three_d.enabled && !validate_only)
      return run_three_d(parameters, three_d, communicator);
    if (three_d.enabled && validate_only)
      return three_d::validate_slice_body(parameters,
                                          three_d,
                                          file,
                                          communicator);
    if (validate_only)
      return validate_mesh(parameters, file, communicator);
    if (!parameters.study.levels.empty())
      return run_refinement_study(parameters, communicator, run.study_values);
    if (accuracy.target > 0)
      return run_to_accuracy_target(parameters, accuracy, communicator);
    const Parameters::AllParameters graded =
      adapt_grading(parameters, communicator);
    if (graded.contact.mode != Parameters::ContactMode::none)
      return run_nip_study(graded, communicator, nullptr, &rolling);
    return run_pressure(graded, communicator);
  });
}
