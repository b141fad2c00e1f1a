// Compiled with -mavx512f: see vector_exp_kernels.hpp.
#include <immintrin.h>
#include <sleef.h>

#include "vector_exp_kernels.hpp"

namespace antipode::detail {

void exp_avx512(double* x, std::size_t n) {
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8)
    _mm512_storeu_pd(x + i, Sleef_cinz_expd8_u10avx512fnofma(_mm512_loadu_pd(x + i)));
  for (; i < n; ++i) x[i] = Sleef_cinz_expd1_u10purec(x[i]);
}

}  // namespace antipode::detail
