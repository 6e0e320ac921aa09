#ifndef rollnip_postprocess_stress_postprocessor_h
#define rollnip_postprocess_stress_postprocessor_h

#include <deal.II/numerics/data_postprocessor.h>

#include <rollnip/material/material_table.h>

namespace rollnip
{
  /**
   * The derived fields of the VTU output: Cauchy stress (Cartesian, polar
   * about the roll axis in the current configuration, and zz), J, the
   * in-plane principal stretches and nominal strains, von Mises and the
   * hydrostatic pressure -tr(sigma)/3, and the in-plane Cauchy stress and
   * Green-Lagrange strain as tensors. Evaluated from the solution, point by
   * point, with evaluate_stress_state().
   */
  class StressPostprocessor : public DataPostprocessor<dim>
  {
  public:
    /// Each cell's law is that of its layer in @p materials.
    explicit StressPostprocessor(const MaterialTable &materials);

    void
    evaluate_vector_field(const DataPostprocessorInputs::Vector<dim> &inputs,
                          std::vector<Vector<double>> &computed) const override;

    std::vector<std::string>
    get_names() const override;

    /// Scalars, then the stress and strain tensors.
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
    get_data_component_interpretation() const override;

    UpdateFlags
    get_needed_update_flags() const override;

  private:
    const MaterialTable &materials;
  };
} // namespace rollnip

#endif
