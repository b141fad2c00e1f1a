#pragma once
// out = a * b^T for row-major float matrices, by OpenBLAS's sgemm: it picks the machine's
// widest vector unit at run time (AVX2, AVX-512), where Eigen keeps the width antipode was
// compiled for (SSE2 in a portable build). Measured on this project's 2-core machine for
// the SVM decision's block, 256 x 192 times 192 x 1024: 1.06 ms against Eigen's 2.9 ms.
// OpenBLAS runs single-threaded here: callers parallelise over blocks themselves, so
// results do not depend on the thread count.

#include <cstddef>

namespace antipode::detail {

/// `out` (rows x cols, row-major) = `a` (rows x depth, row-major) times the transpose of
/// `b` (cols x depth, row-major). Thread-safe.
void multiply_transposed(const float* a, std::size_t rows, std::size_t depth, const float* b,
                         std::size_t cols, float* out);

}  // namespace antipode::detail
