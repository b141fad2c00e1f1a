// Compiled with -mavx: see vector_exp_kernels.hpp.
#include <immintrin.h>
#include <sleef.h>

#include "vector_exp_kernels.hpp"

namespace antipode::detail {

void exp_avx(double* x, std::size_t n) {
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4)
    _mm256_storeu_pd(x + i, Sleef_cinz_expd4_u10avx(_mm256_loadu_pd(x + i)));
  for (; i < n; ++i) x[i] = Sleef_cinz_expd1_u10purec(x[i]);
}

}  // namespace antipode::detail
