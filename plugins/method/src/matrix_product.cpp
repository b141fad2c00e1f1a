#include "matrix_product.hpp"

#include <cblas.h>

#include <mutex>

// OpenBLAS's own, not in cblas.h: it stops the worker threads (OpenBLAS starts them again
// if a product ever asks for more than one thread). Weak, so that a library built without
// threads, which lacks it, still loads.
extern "C" int blas_thread_shutdown_(void) __attribute__((weak));

namespace antipode::detail {

// OpenBLAS starts its worker threads as it is loaded (with OpenCV, by the classifier plugin),
// and each spins, yielding, for about 0.1 s before it sleeps: on 2 cores that took a quarter
// of the CPU from hand sampling in a one-shot `antipode detect` (SampleHands 82 ms against
// 59 ms with OPENBLAS_NUM_THREADS=1, `--trace` of `antipode run trees/detect.yaml`).
void use_calling_threads_only() {
  static std::once_flag once;
  std::call_once(once, [] {
    openblas_set_num_threads(1);
    if (blas_thread_shutdown_ != nullptr) blas_thread_shutdown_();
  });
}

void multiply_transposed(const double* a, std::size_t rows, std::size_t depth, const double* b,
                         std::size_t cols, double* out) {
  use_calling_threads_only();
  cblas_dgemm(CblasRowMajor, CblasNoTrans, CblasTrans, int(rows), int(cols), int(depth), 1.0, a,
              int(depth), b, int(depth), 0.0, out, int(cols));
}

}  // namespace antipode::detail
