#include "kernel_rows.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <Eigen/Core>

namespace antipode::detail {
namespace {

using RowMatrixF = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// A row is computed in blocks of this many entries; the blocks (not the thread count) fix
// every product's arithmetic, so rows are the same for any number of workers.
constexpr std::size_t kBlock = 2048;

}  // namespace

KernelRows::KernelRows(const float* rows, std::size_t n, std::size_t k, const SvmKernel& kernel,
                       std::size_t cache_bytes, int threads)
    : rows_(rows),
      n_(n),
      k_(k),
      kernel_(kernel),
      threads_(threads),
      arena_(threads > 0 ? threads : tbb::task_arena::automatic) {
  squared_norm_.resize(n);
  const Eigen::Map<const RowMatrixF> z(rows, static_cast<Eigen::Index>(n),
                                       static_cast<Eigen::Index>(k));
  for (std::size_t t = 0; t < n; ++t) {
    squared_norm_[t] = z.row(static_cast<Eigen::Index>(t)).squaredNorm();
  }
  diagonal_.resize(n);
  for (std::size_t t = 0; t < n; ++t) diagonal_[t] = apply(squared_norm_[t], t, t);
  const std::size_t capacity = std::clamp<std::size_t>(cache_bytes / (n * sizeof(float)), 2, n);
  // Not value-initialised: the memory is only touched (and paged in) as rows are cached.
  slots_.reset(new float[capacity * n]);
  slot_of_.assign(n, -1);
  row_in_slot_.assign(capacity, 0);
  last_used_.assign(capacity, 0);
}

float KernelRows::apply(float dot, std::size_t s, std::size_t t) const {
  const auto gamma = static_cast<float>(kernel_.gamma);
  if (kernel_.type == SvmKernelType::kRbf) {
    const float distance_squared = std::max(squared_norm_[s] + squared_norm_[t] - 2.0f * dot, 0.0f);
    return std::exp(-gamma * distance_squared);
  }
  const float base = gamma * dot + static_cast<float>(kernel_.coef0);
  float value = base;
  for (int d = 1; d < kernel_.degree; ++d) value *= base;
  return value;
}

void KernelRows::compute(std::size_t s, float* out) {
  const auto k = static_cast<Eigen::Index>(k_);
  const Eigen::Map<const Eigen::VectorXf> z_s(rows_ + s * k_, k);
  const auto block = [&](std::size_t b) {
    const std::size_t first = b * kBlock;
    const std::size_t count = std::min(kBlock, n_ - first);
    const Eigen::Map<const RowMatrixF> z(rows_ + first * k_, static_cast<Eigen::Index>(count), k);
    Eigen::Map<Eigen::VectorXf> dots(out + first, static_cast<Eigen::Index>(count));
    dots.noalias() = z * z_s;
    for (std::size_t t = 0; t < count; ++t) out[first + t] = apply(out[first + t], s, first + t);
  };
  const std::size_t blocks = (n_ + kBlock - 1) / kBlock;
  if (threads_ == 1 || blocks == 1) {
    for (std::size_t b = 0; b < blocks; ++b) block(b);
    return;
  }
  arena_.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks, 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t b = range.begin(); b != range.end(); ++b) block(b);
                      });
  });
}

const float* KernelRows::row(std::size_t s) {
  ++tick_;
  if (slot_of_[s] >= 0) {
    const auto slot = static_cast<std::size_t>(slot_of_[s]);
    last_used_[slot] = tick_;
    return slots_.get() + slot * n_;
  }
  std::size_t slot = used_slots_;
  if (used_slots_ < row_in_slot_.size()) {
    ++used_slots_;
  } else {  // evict the least recently used row
    slot = static_cast<std::size_t>(std::min_element(last_used_.begin(), last_used_.end()) -
                                    last_used_.begin());
    slot_of_[row_in_slot_[slot]] = -1;
  }
  slot_of_[s] = static_cast<std::int64_t>(slot);
  row_in_slot_[slot] = s;
  last_used_[slot] = tick_;
  float* out = slots_.get() + slot * n_;
  compute(s, out);
  ++computed_;
  return out;
}

}  // namespace antipode::detail
