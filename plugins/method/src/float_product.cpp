#include "float_product.hpp"

#include <cblas.h>

#include <mutex>

namespace antipode::detail {

void multiply_transposed(const float* a, std::size_t rows, std::size_t depth, const float* b,
                         std::size_t cols, float* out) {
  static std::once_flag single_threaded;
  std::call_once(single_threaded, [] { openblas_set_num_threads(1); });
  cblas_sgemm(CblasRowMajor, CblasNoTrans, CblasTrans, int(rows), int(cols), int(depth), 1.0f, a,
              int(depth), b, int(depth), 0.0f, out, int(cols));
}

}  // namespace antipode::detail
