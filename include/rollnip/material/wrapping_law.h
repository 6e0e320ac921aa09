#ifndef rollnip_material_wrapping_law_h
#define rollnip_material_wrapping_law_h

#include <deal.II/base/tensor.h>

#include <rollnip/material/material_law.h>

namespace rollnip
{
  /**
   * A law built over another one that keeps its kinematic constraint: the
   * constraint c(F) and the direction dc/dF the pressure unknown acts along
   * are the wrapped law's, whatever the wrapper does to the stresses (a
   * scaled modulus, a viscous overstress on the deviator). The wrapped law
   * must outlive the wrapper.
   */
  template <int d>
  class WrappingLaw : public MaterialLaw<d>
  {
  public:
    dealii::Tensor<2, d>
    pressure_direction(const dealii::Tensor<2, d> &F) const final
    {
      return wrapped.pressure_direction(F);
    }

    double
    constraint(const dealii::Tensor<2, d> &F) const final
    {
      return wrapped.constraint(F);
    }

  protected:
    /// Only binds the reference: @p wrapped may be a member of the derived
    /// law that is constructed after this base.
    explicit WrappingLaw(const MaterialLaw<d> &wrapped)
        : wrapped(wrapped)
    {}

    const MaterialLaw<d> &wrapped;
  };
} // namespace rollnip

#endif
