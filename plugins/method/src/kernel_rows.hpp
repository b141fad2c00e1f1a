#pragma once
// Rows of the kernel matrix K(z_s, z_t) of a training set, for the SVM solver
// (svm_solver.cpp): computed on demand as one matrix-vector product each and kept in a
// least-recently-used cache of whole rows.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <tbb/task_arena.h>

#include "antipode/grasp/svm_model.hpp"

namespace antipode::detail {

class KernelRows {
 public:
  // `rows`: n x k row-major, borrowed (must outlive this object). `cache_bytes` holds at least
  // two rows. `threads` computes a row's blocks (0: all).
  KernelRows(const float* rows, std::size_t n, std::size_t k, const SvmKernel& kernel,
             std::size_t cache_bytes, int threads);

  // Row s: K(z_s, z_t) for every t. The pointer stays valid until two further rows have
  // been asked for (the cache evicts the least recently used row first).
  const float* row(std::size_t s);
  // K(z_s, z_s).
  float diagonal(std::size_t s) const { return diagonal_[s]; }
  std::size_t size() const { return n_; }
  // Rows computed so far (cache misses).
  std::int64_t computed() const { return computed_; }

 private:
  void compute(std::size_t s, float* out);
  float apply(float dot, std::size_t s, std::size_t t) const;

  const float* rows_;
  std::size_t n_;
  std::size_t k_;
  SvmKernel kernel_;
  int threads_;
  tbb::task_arena arena_;            // the row workers, when threads_ is not 1
  std::vector<float> squared_norm_;  // |z_t|^2, for the Gaussian kernel
  std::vector<float> diagonal_;
  std::unique_ptr<float[]> slots_;        // capacity x n, touched as rows arrive
  std::vector<std::int64_t> slot_of_;     // per row: its slot or -1
  std::vector<std::size_t> row_in_slot_;  // per slot: its row
  std::vector<std::int64_t> last_used_;   // per slot: the tick of its last use
  std::size_t used_slots_ = 0;
  std::int64_t tick_ = 0;
  std::int64_t computed_ = 0;
};

}  // namespace antipode::detail
