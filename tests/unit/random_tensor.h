#ifndef rollnip_tests_random_tensor_h
#define rollnip_tests_random_tensor_h

#include <deal.II/base/tensor.h>

#include <random>

namespace rollnip
{
  namespace testing
  {
    /// A d x d tensor with entries uniform in [-scale, scale]: the random
    /// states at which the material-law tests compare a law with a
    /// closed form, a finite difference or another law.
    template <int d>
    dealii::Tensor<2, d>
    random_tensor(std::mt19937 &gen, const double scale)
    {
      std::uniform_real_distribution<double> u(-scale, scale);
      dealii::Tensor<2, d>                   t;
      for (unsigned int i = 0; i < d; ++i)
        for (unsigned int j = 0; j < d; ++j)
          t[i][j] = u(gen);
      return t;
    }
  } // namespace testing
} // namespace rollnip

#endif
