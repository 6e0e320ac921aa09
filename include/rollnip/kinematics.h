#ifndef rollnip_kinematics_h
#define rollnip_kinematics_h

#include <deal.II/base/tensor.h>

/**
 * Kinematics of the deformation gradient F that the material laws, the
 * follower load and the surface tractions share: cof F maps a reference
 * area normal N dA to the current one n da = cof(F) N dA. None of it
 * belongs to a material.
 */
namespace rollnip
{
  /// cof F = J F^-T. In 2D it is written out: it is then linear in F and
  /// defined for any F, so it also serves for cof(Grad du) in a tangent.
  template <int d>
  dealii::Tensor<2, d>
  cofactor(const dealii::Tensor<2, d> &F)
  {
    if constexpr (d == 2)
      {
        dealii::Tensor<2, d> c;
        c[0][0] = F[1][1];
        c[0][1] = -F[1][0];
        c[1][0] = -F[0][1];
        c[1][1] = F[0][0];
        return c;
      }
    else
      return determinant(F) * transpose(invert(F));
  }

  /// d(cof F)[dF]: cof(dF) in 2D, where cof is linear, and
  /// J tr(F^-1 dF) F^-T - J F^-T dF^T F^-T in 3D.
  template <int d>
  dealii::Tensor<2, d>
  cofactor_derivative(const dealii::Tensor<2, d> &F,
                      const dealii::Tensor<2, d> &dF)
  {
    if constexpr (d == 2)
      return cofactor(dF);
    else
      {
        const dealii::Tensor<2, d> F_inv_T = transpose(invert(F));
        const double               J       = determinant(F);
        return J * (trace(invert(F) * dF) * F_inv_T -
                    F_inv_T * transpose(dF) * F_inv_T);
      }
  }
} // namespace rollnip

#endif
