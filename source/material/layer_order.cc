#include <deal.II/base/mpi.h>

#include <rollnip/material/layer_order.h>
#include <rollnip/parameter_entries.h>
#include <rollnip/parameters.h>

#include <algorithm>
#include <iostream>
#include <sstream>

namespace rollnip
{
  namespace LayerOrder
  {
    void
    declare(ParameterHandler &prm)
    {
      Parameters::declare_documented(
        prm,
        "Layer order",
        "",
        Patterns::Selection("|core first|top first"),
        "The order of the per-layer lists of a layered cover (C1, C2, "
        "Hardness, Layer thicknesses, Poisson ratio, Bulk modulus): core "
        "first (layer 1 on the core), or "
        "top first (layer 1 the surface; the lists are reversed when "
        "read); empty: core first, with a warning for a layered cover");
    }

    void
    apply(ParameterHandler     &prm,
          Parameters::Material &material,
          const std::string    &prefix)
    {
      prm.enter_subsection("Material");
      const std::string order = prm.get("Layer order");
      prm.leave_subsection();
      // A count mismatch is refused by the validation that follows.
      if (material.n_layers() < 2 ||
          material.layer_thicknesses.size() != material.n_layers() ||
          material.layer_C2.size() != material.n_layers())
        return;
      if (order == "top first")
        {
          std::reverse(material.layer_C1.begin(), material.layer_C1.end());
          std::reverse(material.layer_C2.begin(), material.layer_C2.end());
          std::reverse(material.layer_thicknesses.begin(),
                       material.layer_thicknesses.end());
          // One value stands for all layers; a list is per layer.
          std::reverse(material.layer_poisson_ratio.begin(),
                       material.layer_poisson_ratio.end());
          std::reverse(material.layer_bulk_modulus.begin(),
                       material.layer_bulk_modulus.end());
          return;
        }
      if (!order.empty() ||
          Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        return;
      const auto        &t = material.layer_thicknesses;
      std::ostringstream s;
      s << "rollnip: warning: " << prefix
        << "Material/Layer order is not stated: the layers are read from "
           "the core out, layer 1 ("
        << t.front() << " mm, G = "
        << 2 * (material.layer_C1.front() + material.layer_C2.front())
        << " MPa) on the core, layer " << t.size() << " (" << t.back()
        << " mm, G = "
        << 2 * (material.layer_C1.back() + material.layer_C2.back())
        << " MPa) the surface; set Layer order = core first to confirm, or "
           "top first if the lists start at the surface";
      std::cerr << s.str() << std::endl;
    }

    void
    apply(ParameterHandler &prm, Parameters::AllParameters &parameters)
    {
      apply(prm, parameters.material, "");
      if (!parameters.mating_roll.covered)
        return;
      prm.enter_subsection("Mating roll");
      apply(prm, parameters.mating_roll.material, "Mating roll/");
      prm.leave_subsection();
    }
  } // namespace LayerOrder
} // namespace rollnip
