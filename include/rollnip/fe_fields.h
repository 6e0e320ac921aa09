#ifndef rollnip_fe_fields_h
#define rollnip_fe_fields_h

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values_extractors.h>

#include <rollnip/global.h>

/**
 * The fields of a roll body's mixed element and the quadrature of its
 * integrals, defined once for every user (assembly, load, output,
 * postprocessing): the displacement u is components 0 to dim - 1 and the
 * pressure unknown q is component dim.
 */
namespace rollnip
{
  namespace FEFields
  {
    /// The component of the pressure unknown q.
    constexpr unsigned int pressure_component = dim;

    /// The displacement u.
    inline const FEValuesExtractors::Vector displacement(0);
    /// The pressure unknown q.
    inline const FEValuesExtractors::Scalar pressure(pressure_component);

    /// Whether shape function @p i of @p fe belongs to q.
    inline bool
    is_pressure(const FiniteElement<dim> &fe, const unsigned int i)
    {
      return fe.system_to_component_index(i).first == pressure_component;
    }

    /// The components of u in @p fe.
    inline ComponentMask
    displacement_mask(const FiniteElement<dim> &fe)
    {
      return fe.component_mask(displacement);
    }

    /// The components of q in @p fe.
    inline ComponentMask
    pressure_mask(const FiniteElement<dim> &fe)
    {
      return fe.component_mask(pressure);
    }

    /// Gauss with degree + 1 points per direction for the cell integrals:
    /// exact for the tangent of the undeformed affine cell, and the points
    /// where stresses are evaluated.
    inline QGauss<dim>
    cell_quadrature(const FiniteElement<dim> &fe)
    {
      return QGauss<dim>(fe.degree + 1);
    }

    /// Gauss with degree + 1 points for the face integrals (the load, the
    /// error indicators).
    inline QGauss<dim - 1>
    face_quadrature(const FiniteElement<dim> &fe)
    {
      return QGauss<dim - 1>(fe.degree + 1);
    }
  } // namespace FEFields
} // namespace rollnip

#endif
