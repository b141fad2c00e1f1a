#include "matrix_product.hpp"

#include <cblas.h>

#include <mutex>

namespace antipode::detail {
namespace {

void single_threaded() {
  static std::once_flag once;
  std::call_once(once, [] { openblas_set_num_threads(1); });
}

}  // namespace

void multiply_transposed(const double* a, std::size_t rows, std::size_t depth, const double* b,
                         std::size_t cols, double* out) {
  single_threaded();
  cblas_dgemm(CblasRowMajor, CblasNoTrans, CblasTrans, int(rows), int(cols), int(depth), 1.0, a,
              int(depth), b, int(depth), 0.0, out, int(cols));
}

}  // namespace antipode::detail
