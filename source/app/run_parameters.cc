#include <rollnip/app/run_parameters.h>

namespace rollnip
{
  void
  RunParameters::read(const std::string &filename)
  {
    ParameterHandler prm;
    scene.read(filename, prm);
    face.parse(prm);
    face.validate();
    accuracy.parse(prm);
    accuracy.check(scene);
    study_values.parse(prm, scene);
    rolling.parse(prm,
                  scene.material.n_layers(),
                  scene.contact.surface_speed,
                  scene.mating_roll.covered
                    ? scene.mating_roll.material.n_layers()
                    : 0);
    rolling.validate(scene);
    three_d.parse(prm);
  }
} // namespace rollnip
