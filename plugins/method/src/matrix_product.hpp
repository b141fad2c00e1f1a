#pragma once
// out = a * b^T for row-major double matrices, by OpenBLAS's dgemm: it picks the machine's
// widest vector unit at run time (AVX2, AVX-512), where Eigen keeps the width antipode was
// compiled for (SSE2 in a portable build). Because the kernel is chosen per CPU, the last
// bits of a product differ between CPUs (svm_model.cpp says why the SVM works in double).
// OpenBLAS runs single-threaded here: callers parallelise over blocks themselves, so
// results do not depend on the thread count.

#include <cstddef>

namespace antipode::detail {

/// `out` (rows x cols, row-major) = `a` (rows x depth, row-major) times the transpose of
/// `b` (cols x depth, row-major). Thread-safe.
void multiply_transposed(const double* a, std::size_t rows, std::size_t depth, const double* b,
                         std::size_t cols, double* out);

/// Makes OpenBLAS run every product on the calling thread and stops its worker threads
/// (the first call; later calls do nothing). multiply_transposed() calls it; a model's
/// loader calls it too, as soon as the library is loaded. Thread-safe.
void use_calling_threads_only();

}  // namespace antipode::detail
