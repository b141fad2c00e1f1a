#include "antipode/grasp/svm_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <Eigen/Core>

#include "antipode/core/binary_file.hpp"
#include "antipode/core/error.hpp"
#include "image_options_io.hpp"
#include "matrix_product.hpp"
#include "number_codes.hpp"
#include "vector_exp.hpp"

namespace antipode {
namespace {

constexpr const char* kMagic = "ANTPSVM1";
// 1: descriptors with four alignment angles and no occlusion statistics; not read.
// 2: support vectors in single precision; not read.
// 3: support vectors in half precision; not read.
// 4: basis in 8-bit codes; support vectors in half precision (the leading components) and
//    8-bit codes (the rest).
// 5: Platt scaling after the training facts. 6: the operating points after it.
constexpr std::uint32_t kVersion = 6;
// The largest finite half-precision number.
constexpr float kHalfMax = 65504.0f;
constexpr int kMaxOption = 4096;  // bound on each image option read from a file

using RowMatrixF = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using ConstRowMapF = Eigen::Map<const RowMatrixF>;
using RowMatrixD = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

std::string number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// Without an early exit, so that the compiler vectorises it: a model's 4 million numbers
// are all read on every load (|v| <= max is false for NaN and the infinities).
template <typename T>
bool all_finite(const std::vector<T>& values) {
  bool finite = true;
  for (const T v : values) finite &= std::abs(v) <= std::numeric_limits<T>::max();
  return finite;
}

// Whether a support vector number stored at half precision (svm_model.hpp) is too large.
bool half_precision_overflow(const SvmModel& m) {
  const std::size_t k = m.components();
  const std::size_t h = std::min(SvmModel::kHalfPrecisionComponents, k);
  bool over = false;
  for (std::size_t i = 0; k > 0 && i + k <= m.support_vectors.size(); i += k) {
    for (std::size_t j = 0; j < h; ++j) over |= std::abs(m.support_vectors[i + j]) > kHalfMax;
  }
  return over;
}

std::string sizes_problem(const SvmModel& m) {
  const std::size_t d = m.descriptor.image.descriptor_size();
  const std::size_t k = m.components();
  if (m.mean.size() != d) {
    return "mean of " + std::to_string(m.mean.size()) + " numbers, but the descriptor has " +
           std::to_string(d);
  }
  if (k == 0 || k > d) return "reduction to " + std::to_string(k) + " components";
  if (m.basis.size() != k * d) return "PCA basis size disagrees with its components";
  if (m.support_vector_count() == 0) return "no support vectors";
  if (m.support_vectors.size() != m.support_vector_count() * k) {
    return "support vectors disagree with their coefficients or the components";
  }
  return "";
}

std::string image_problem(const HandImageOptions& o) {
  for (const int v : {o.cells_along, o.cells_across, o.cell_px, o.block_cells, o.bins}) {
    if (v < 1 || v > kMaxOption) return "image option out of range: " + std::to_string(v);
  }
  try {
    o.validate();
  } catch (const Error& e) {
    return e.message();
  }
  return "";
}

// The operating points (SvmOperatingPoints): finite, relaxed no higher than accept, and
// probabilities only of a calibrated model, within [0, 1].
std::string operating_problem(const SvmModel& m) {
  const SvmOperatingPoints& o = m.operating;
  if (!std::isfinite(o.accept) || !std::isfinite(o.relaxed)) return "non-finite operating points";
  if (o.relaxed > o.accept) return "relaxed threshold above the accepting one";
  if (!o.probability) return "";
  if (!m.calibration.fitted()) return "operating points are probabilities of an uncalibrated model";
  if (o.relaxed < 0.0 || o.accept > 1.0) return "probability operating points outside [0, 1]";
  return "";
}

std::string numbers_problem(const SvmModel& m) {
  const SvmDescriptorSpec& s = m.descriptor;
  for (const double v : {s.depth_m, s.max_aperture_m, s.height_m}) {
    if (!(std::isfinite(v) && v > 0.0)) return "hand length not a positive number";
  }
  if (!all_finite(m.mean) || !all_finite(m.basis) || !all_finite(m.scale) ||
      !all_finite(m.support_vectors) || !all_finite(m.alpha) || !std::isfinite(m.rho)) {
    return "non-finite number";
  }
  const SvmKernel& k = m.kernel;
  if (k.type == SvmKernelType::kPolynomial && (k.degree < 1 || k.degree > 10)) {
    return "kernel degree " + std::to_string(k.degree);
  }
  if (!(std::isfinite(k.gamma) && k.gamma > 0.0 && std::isfinite(k.coef0) && std::isfinite(k.C) &&
        k.C > 0.0)) {
    return "invalid kernel parameters (gamma and C must be positive)";
  }
  if (half_precision_overflow(m)) {
    return "support vector number beyond half precision's range (65504)";
  }
  if (!(std::isfinite(m.info.cv_accuracy) && m.info.cv_accuracy <= 1.0)) {
    return "invalid cross-validation accuracy";
  }
  if (!std::isfinite(m.calibration.a) || !std::isfinite(m.calibration.b)) {
    return "non-finite calibration";
  }
  return operating_problem(m);
}

std::string model_problem(const SvmModel& m) {
  std::string problem = image_problem(m.descriptor.image);
  if (problem.empty()) problem = sizes_problem(m);
  if (problem.empty()) problem = numbers_problem(m);
  return problem;
}

// ---------------------------------------------------------------------------------------
// How model files store the basis and the support vectors (format 4; number_codes.hpp):
// each basis row as 8-bit codes; support vector component j at half precision when
// j < kHalfPrecisionComponents, else as 8-bit codes, one exponent per component.

std::size_t half_components(const SvmModel& m) {
  return std::min(SvmModel::kHalfPrecisionComponents, m.components());
}

// Coded numbers as a file holds them: one exponent per run, the runs' codes in order.
struct StoredCodes {
  std::vector<std::int8_t> exponents;
  std::vector<std::int8_t> codes;
};

void put_codes(const StoredCodes& s, BinaryWriter& w) {
  w.put_vector(s.exponents);
  w.put_vector(s.codes);
}

StoredCodes get_codes(BinaryReader& r) {
  StoredCodes s;
  s.exponents = r.get_vector<std::int8_t>();
  s.codes = r.get_vector<std::int8_t>();
  const std::string problem = detail::codes_problem(s.exponents, s.codes);
  if (!problem.empty()) r.fail("inconsistent: " + problem);
  return s;
}

// Decodes `runs` runs of `count` numbers from `s`, run i into `stride`-apart numbers from
// run(i); a file whose parts disagree fails through `r`.
template <typename RunStart>
void decode_runs(const StoredCodes& s, std::size_t runs, std::size_t count, std::size_t stride,
                 const RunStart& run, const BinaryReader& r) {
  if (s.exponents.size() != runs || s.codes.size() != runs * count) {
    r.fail("inconsistent: stored codes disagree with the model's sizes");
  }
  for (std::size_t i = 0; i < runs; ++i) {
    detail::decode_codes(s.codes.data() + i * count, count, s.exponents[i], run(i), stride);
  }
}

void put_basis(const SvmModel& m, BinaryWriter& w) {
  const std::size_t d = m.input_dimension();
  StoredCodes s;
  for (std::size_t j = 0; j < m.components(); ++j) {
    s.exponents.push_back(detail::append_codes({m.basis.data() + j * d, d, 1}, s.codes));
  }
  put_codes(s, w);
}

void put_support_vectors(const SvmModel& m, BinaryWriter& w) {
  const std::size_t k = m.components();
  const std::size_t h = half_components(m);
  const std::size_t n = m.support_vector_count();
  std::vector<std::uint16_t> halves;  // n x h, row-major
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < h; ++j)
      halves.push_back(detail::half_bits(m.support_vectors[i * k + j]));
  }
  StoredCodes s;  // component by component
  for (std::size_t j = h; j < k; ++j) {
    s.exponents.push_back(detail::append_codes({m.support_vectors.data() + j, n, k}, s.codes));
  }
  w.put_vector(halves);
  put_codes(s, w);
}

// The support vectors of a file (`halves`, then `coded`) for a model whose components and
// coefficients `m` already holds.
std::vector<float> decode_support_vectors(const SvmModel& m,
                                          const std::vector<std::uint16_t>& halves,
                                          const StoredCodes& coded, const BinaryReader& r) {
  const std::size_t k = m.components();
  const std::size_t h = half_components(m);
  const std::size_t n = m.support_vector_count();
  if (halves.size() != n * h || coded.codes.size() != n * (k - h)) {  // before allocating
    r.fail("inconsistent: support vectors disagree with their coefficients or the components");
  }
  std::vector<float> values(n * k);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < h; ++j)
      values[i * k + j] = detail::from_half_bits(halves[i * h + j]);
  }
  decode_runs(
      coded, k - h, n, k, [&](std::size_t c) { return values.data() + h + c; }, r);
  return values;
}

void check_threads(int threads) {
  if (threads < 0) throw Error("SVM model: threads must be >= 0, got " + std::to_string(threads));
}

// Runs body(block) for every block of kBlockRows rows, in parallel.
template <typename Body>
void for_each_block(std::size_t n, int threads, const Body& body) {
  check_threads(threads);
  const std::size_t blocks = (n + SvmModel::kBlockRows - 1) / SvmModel::kBlockRows;
  if (blocks == 0) return;
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks, 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t b = range.begin(); b != range.end(); ++b) body(b);
                      });
  });
}

// Decision values are computed in double precision from the model's single-precision
// numbers. OpenBLAS picks its matrix kernel for the CPU it runs on, and kernels round
// differently: in single precision, decision values differed in the 7th digit between CPUs,
// enough to reorder hands of nearly equal score and so change which grasp a clear-the-box
// cycle executes - and every cycle after it. In double precision they differ in the 16th
// digit, below any difference between two hands' scores. The reduced features z are
// rounded to single precision, as reduce() returns them for training, so that
// decision_values() and decision_values_reduced(reduce()) agree exactly.

// Rows [first, first + count) of `rows` (width `dim`), minus `offset`, in a zero-padded
// kBlockRows x dim matrix.
RowMatrixD padded_block(const float* rows, std::size_t first, std::size_t count, std::size_t dim,
                        const std::vector<float>* offset) {
  RowMatrixD block = RowMatrixD::Zero(SvmModel::kBlockRows, static_cast<Eigen::Index>(dim));
  for (std::size_t r = 0; r < count; ++r) {
    const float* row = rows + (first + r) * dim;
    for (std::size_t c = 0; c < dim; ++c) {
      block(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) =
          offset == nullptr ? double(row[c]) : double(row[c]) - double((*offset)[c]);
    }
  }
  return block;
}

// The model's numbers in double precision are converted once per call of reduce() or
// decision_values() and shared, read-only, by every block: converting them per block (4
// blocks for table_mug.pcd's 476 screened hands) made the whole detection about 7% slower
// (docs/results.md, Speed).

// The PCA basis, components x input dimension.
RowMatrixD double_basis(const SvmModel& m) {
  return ConstRowMapF(m.basis.data(), Eigen::Index(m.components()),
                      Eigen::Index(m.input_dimension()))
      .cast<double>();
}

// The support vectors, and their squared norms for the Gaussian kernel.
struct DoubleSupport {
  RowMatrixD vectors;          ///< support vectors x components
  Eigen::RowVectorXd squared;  ///< empty for the polynomial kernel

  // Converted by `threads` workers, block by block: the first call's 35 MB (for the shipped
  // model) are written, and their pages faulted in, by every worker at once.
  static DoubleSupport of(const SvmModel& m, int threads) {
    const auto n = Eigen::Index(m.support_vector_count());
    const auto k = Eigen::Index(m.components());
    const bool gaussian = m.kernel.type == SvmKernelType::kRbf;
    DoubleSupport out;
    out.vectors.resize(n, k);
    if (gaussian) out.squared.resize(n);
    for_each_block(std::size_t(n), threads, [&](std::size_t b) {
      const auto first = Eigen::Index(b * SvmModel::kBlockRows);
      const Eigen::Index rows = std::min(Eigen::Index(SvmModel::kBlockRows), n - first);
      auto block = out.vectors.middleRows(first, rows);
      block = ConstRowMapF(m.support_vectors.data() + first * k, rows, k).cast<double>();
      if (gaussian) out.squared.segment(first, rows) = block.rowwise().squaredNorm().transpose();
    });
    return out;
  }
};

// The reduced features of a block, each rounded to single precision.
RowMatrixD reduce_block(const SvmModel& m, const RowMatrixD& basis, const float* rows,
                        std::size_t first, std::size_t count) {
  const auto d = static_cast<Eigen::Index>(m.input_dimension());
  const auto k = static_cast<Eigen::Index>(m.components());
  const RowMatrixD centred = padded_block(rows, first, count, m.input_dimension(), &m.mean);
  RowMatrixD z(centred.rows(), k);
  detail::multiply_transposed(centred.data(), std::size_t(centred.rows()), std::size_t(d),
                              basis.data(), std::size_t(k), z.data());
  for (Eigen::Index j = 0; j < k; ++j) z.col(j) *= double(m.scale[static_cast<std::size_t>(j)]);
  return z.cast<float>().cast<double>();
}

// Support vectors are scored in chunks of this many, so that a chunk's kernel values
// (kBlockRows x kChunk doubles, 1 MiB) stay in cache between the matrix product, the
// kernel function and the weighted sum.
constexpr Eigen::Index kSupportChunk = 1024;

// K(z_r, sv_i) for the first `rows` rows r of z and every support vector i, in place of
// their dot products `k` (the zero rows that pad a block follow them and are left as they
// are: their values are never read); `z_squared` and `sv_squared` are the rows' squared
// norms (only the Gaussian kernel uses them: |z - sv|^2 = |z|^2 + |sv|^2 - 2 z . sv).
void apply_kernel(const SvmKernel& kernel, Eigen::Index rows, const Eigen::VectorXd& z_squared,
                  const Eigen::RowVectorXd& sv_squared, RowMatrixD& k) {
  if (kernel.type == SvmKernelType::kRbf) {
    // The exponents row by row, then their exponentials in one pass over the rows (a
    // RowMatrixD's rows are contiguous) at the CPU's vector width (vector_exp.hpp).
    for (Eigen::Index r = 0; r < rows; ++r) {
      auto row = k.row(r).array();
      row = (sv_squared.array() + z_squared(r) - 2.0 * row).max(0.0) * -kernel.gamma;
    }
    detail::exp_in_place(k.data(), static_cast<std::size_t>(rows * k.cols()));
    return;
  }
  const Eigen::ArrayXXd base = kernel.gamma * k.topRows(rows).array() + kernel.coef0;
  Eigen::ArrayXXd power = base;
  for (int i = 1; i < kernel.degree; ++i) power *= base;
  k.topRows(rows) = power.matrix();
}

// f(z_r) for the rows of z (kBlockRows x components), written to out[first + r] for the
// first `count` rows.
void score_block(const SvmModel& m, const DoubleSupport& support, const RowMatrixD& z,
                 std::size_t first, std::size_t count, double* out) {
  const auto k = static_cast<Eigen::Index>(m.components());
  const auto nsv = static_cast<Eigen::Index>(m.support_vector_count());
  const bool gaussian = m.kernel.type == SvmKernelType::kRbf;
  const Eigen::VectorXd z_squared =
      gaussian ? z.rowwise().squaredNorm().eval() : Eigen::VectorXd::Zero(z.rows());
  const Eigen::Map<const Eigen::VectorXd> alpha(m.alpha.data(), nsv);
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(z.rows());
  RowMatrixD values;
  for (Eigen::Index c = 0; c < nsv; c += kSupportChunk) {
    const Eigen::Index width = std::min(kSupportChunk, nsv - c);
    const Eigen::RowVectorXd sv_squared =
        gaussian ? support.squared.segment(c, width).eval() : Eigen::RowVectorXd::Zero(width);
    values.resize(z.rows(), width);
    detail::multiply_transposed(z.data(), std::size_t(z.rows()), std::size_t(k),
                                support.vectors.data() + c * k, std::size_t(width), values.data());
    apply_kernel(m.kernel, Eigen::Index(count), z_squared, sv_squared, values);
    sum.noalias() += values * alpha.segment(c, width);
  }
  for (std::size_t r = 0; r < count; ++r)
    out[first + r] = sum(static_cast<Eigen::Index>(r)) - m.rho;
}

std::size_t block_rows(std::size_t n, std::size_t block) {
  return std::min(SvmModel::kBlockRows, n - block * SvmModel::kBlockRows);
}

void check_dimension(const SvmModel& m, std::size_t dim) {
  if (dim != m.input_dimension()) {
    throw Error("SVM model: descriptors of " + std::to_string(dim) +
                " numbers, but the model takes " + std::to_string(m.input_dimension()));
  }
}

}  // namespace

const char* kernel_name(SvmKernelType type) { return type == SvmKernelType::kRbf ? "rbf" : "poly"; }

SvmKernelType kernel_type(const std::string& name) {
  if (name == "poly") return SvmKernelType::kPolynomial;
  if (name == "rbf") return SvmKernelType::kRbf;
  throw Error("unknown kernel '" + name + "' (use poly or rbf)");
}

SvmDescriptorSpec SvmDescriptorSpec::of(const HandImageOptions& image,
                                        const HandGeometry& geometry) {
  SvmDescriptorSpec spec;
  spec.image = image;
  spec.depth_m = geometry.depth_m;
  spec.max_aperture_m = geometry.max_aperture_m;
  spec.height_m = geometry.height_m;
  return spec;
}

std::string SvmDescriptorSpec::describe() const {
  return "a " + number(depth_m) + " m deep, " + number(max_aperture_m) + " m wide, " +
         number(height_m) + " m high hand with " + std::to_string(image.cells_along) + " x " +
         std::to_string(image.cells_across) + " HOG cells of " + std::to_string(image.cell_px) +
         " px (" + std::to_string(image.block_cells) + " x " + std::to_string(image.block_cells) +
         " cell blocks, " + std::to_string(image.bins) + " bins, points drawn " +
         std::to_string(image.point_radius_px) + " px wide, " +
         (image.normal_features ? "with" : "without") + " normal statistics, " +
         (image.occlusion_features ? "with" : "without") + " occlusion statistics, " + name + ")";
}

bool SvmDescriptorSpec::matches(const SvmDescriptorSpec& o) const {
  const auto near = [](double a, double b) { return std::abs(a - b) <= 1e-9; };
  const HandImageOptions& a = image;
  const HandImageOptions& b = o.image;
  return name == o.name && a.cells_along == b.cells_along && a.cells_across == b.cells_across &&
         a.cell_px == b.cell_px && a.block_cells == b.block_cells && a.bins == b.bins &&
         a.point_radius_px == b.point_radius_px && a.normal_features == b.normal_features &&
         a.occlusion_features == b.occlusion_features && near(depth_m, o.depth_m) &&
         near(max_aperture_m, o.max_aperture_m) && near(height_m, o.height_m);
}

void SvmModel::validate(const std::string& context) const {
  const std::string problem = model_problem(*this);
  if (!problem.empty()) throw Error(context + ": " + problem);
}

std::vector<float> SvmModel::reduce(const float* rows, std::size_t n, std::size_t dim,
                                    int threads) const {
  check_dimension(*this, dim);
  const std::size_t k = components();
  std::vector<float> reduced(n * k);
  check_threads(threads);
  if (n == 0) return reduced;
  const RowMatrixD basis = double_basis(*this);
  for_each_block(n, threads, [&](std::size_t b) {
    const std::size_t first = b * kBlockRows;
    const std::size_t count = block_rows(n, b);
    const RowMatrixD z = reduce_block(*this, basis, rows, first, count);
    for (std::size_t r = 0; r < count; ++r) {
      for (std::size_t j = 0; j < k; ++j) {
        reduced[(first + r) * k + j] =
            static_cast<float>(z(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(j)));
      }
    }
  });
  return reduced;
}

std::vector<double> SvmModel::decision_values(const float* rows, std::size_t n, std::size_t dim,
                                              int threads) const {
  check_dimension(*this, dim);
  std::vector<double> values(n);
  check_threads(threads);
  if (n == 0) return values;
  const RowMatrixD basis = double_basis(*this);
  const DoubleSupport support = DoubleSupport::of(*this, threads);
  for_each_block(n, threads, [&](std::size_t b) {
    const std::size_t first = b * kBlockRows;
    const std::size_t count = block_rows(n, b);
    score_block(*this, support, reduce_block(*this, basis, rows, first, count), first, count,
                values.data());
  });
  return values;
}

std::vector<double> SvmModel::decision_values(const std::vector<std::vector<float>>& descriptors,
                                              int threads) const {
  std::vector<float> rows;
  rows.reserve(descriptors.size() * input_dimension());
  for (const auto& d : descriptors) {
    check_dimension(*this, d.size());
    rows.insert(rows.end(), d.begin(), d.end());
  }
  return decision_values(rows.data(), descriptors.size(), input_dimension(), threads);
}

std::vector<double> SvmModel::decision_values_reduced(const float* reduced, std::size_t n,
                                                      int threads) const {
  std::vector<double> values(n);
  check_threads(threads);
  if (n == 0) return values;
  const DoubleSupport support = DoubleSupport::of(*this, threads);
  for_each_block(n, threads, [&](std::size_t b) {
    const std::size_t first = b * kBlockRows;
    const std::size_t count = block_rows(n, b);
    score_block(*this, support, padded_block(reduced, first, count, components(), nullptr), first,
                count, values.data());
  });
  return values;
}

void SvmModel::round_support_vectors() {
  const std::size_t k = components();
  const std::size_t h = half_components(*this);
  if (support_vectors.size() != support_vector_count() * k) {
    throw Error("SVM model: support vectors disagree with their coefficients or the components");
  }
  for (std::size_t i = 0; i < support_vectors.size(); ++i) {
    float& v = support_vectors[i];
    if (!std::isfinite(v) || (i % k < h && std::abs(v) > kHalfMax)) {
      throw Error(
          "SVM model: support vector number " + number(v) +
          (std::isfinite(v) ? " is beyond half precision's range (65504)" : " is not finite"));
    }
    if (i % k < h) v = detail::round_to_half(v);
  }
  for (std::size_t j = h; j < k; ++j) {
    detail::round_to_codes(support_vectors.data() + j, support_vector_count(), k);
  }
}

void SvmModel::round_basis() {
  const std::size_t d = input_dimension();
  if (basis.size() != components() * d) {
    throw Error("SVM model: PCA basis size disagrees with its components");
  }
  if (!all_finite(basis)) throw Error("SVM model: non-finite PCA basis number");
  for (std::size_t j = 0; j < components(); ++j) detail::round_to_codes(basis.data() + j * d, d, 1);
}

void SvmModel::check_compatible(const HandImageOptions& image, const HandGeometry& geometry,
                                const std::string& model_name) const {
  const SvmDescriptorSpec wanted = SvmDescriptorSpec::of(image, geometry);
  if (descriptor.matches(wanted)) return;
  throw Error(model_name + " was trained for " + descriptor.describe() + "; this hand set has " +
              wanted.describe() +
              " (train a model for this hand: antipode train --out my.model --set "
              "sampler.hand=GRIPPER.yaml, then give the classifier model: my.model; "
              "docs/your-own-data.md)");
}

void SvmModel::save(const std::string& path) const {
  validate("SVM model for " + path);
  BinaryWriter w(kMagic, kVersion);
  w.put_string(descriptor.name);
  detail::put_image_options(w, descriptor.image);
  w.put(descriptor.depth_m);
  w.put(descriptor.max_aperture_m);
  w.put(descriptor.height_m);
  w.put_string(kernel_name(kernel.type));
  w.put<std::int32_t>(kernel.degree);
  w.put(kernel.gamma);
  w.put(kernel.coef0);
  w.put(kernel.C);
  w.put_vector(mean);
  put_basis(*this, w);
  w.put_vector(scale);
  put_support_vectors(*this, w);
  w.put_vector(alpha);
  w.put(rho);
  w.put<std::uint64_t>(info.positives);
  w.put<std::uint64_t>(info.negatives);
  w.put<std::uint64_t>(info.seed);
  w.put(info.cv_accuracy);
  w.put_string(info.description);
  w.put(calibration.a);
  w.put(calibration.b);
  w.put<std::uint64_t>(calibration.examples);
  w.put<std::uint8_t>(operating.probability ? 1 : 0);
  w.put(operating.accept);
  w.put(operating.relaxed);
  w.write(path);
}

SvmModel SvmModel::load(const std::string& path) {
  detail::use_calling_threads_only();  // before OpenBLAS's idle workers take CPU from others
  BinaryReader r(path, kMagic, kVersion, "classifier model");
  if (r.version() < 4) {
    r.fail("format version " + std::to_string(r.version()) +
           " was written by an older antipode; retrain with `antipode train`");
  }
  SvmModel m;
  m.descriptor.name = r.get_string();
  if (const std::string today = SvmDescriptorSpec{}.name; m.descriptor.name != today) {
    // Another descriptor version lays its numbers out differently: nothing else would match.
    r.fail("made for descriptor " + m.descriptor.name + ", but this antipode computes " + today +
           "; retrain with `antipode train`");
  }
  m.descriptor.image = detail::get_image_options(r);
  try {
    m.descriptor.image.validate();  // a damaged file must not ask for a gigabyte image
  } catch (const Error& e) {
    r.fail(e.message());
  }
  m.descriptor.depth_m = r.get<double>();
  m.descriptor.max_aperture_m = r.get<double>();
  m.descriptor.height_m = r.get<double>();
  const std::string kernel = r.get_string();
  try {
    m.kernel.type = kernel_type(kernel);
  } catch (const Error& e) {
    r.fail(e.message());
  }
  m.kernel.degree = r.get<std::int32_t>();
  m.kernel.gamma = r.get<double>();
  m.kernel.coef0 = r.get<double>();
  m.kernel.C = r.get<double>();
  m.mean = r.get_vector<float>();
  const StoredCodes basis = get_codes(r);
  m.scale = r.get_vector<float>();
  const std::vector<std::uint16_t> halves = r.get_vector<std::uint16_t>();
  const StoredCodes coded = get_codes(r);
  m.alpha = r.get_vector<double>();
  m.rho = r.get<double>();
  m.info.positives = r.get<std::uint64_t>();
  m.info.negatives = r.get<std::uint64_t>();
  m.info.seed = r.get<std::uint64_t>();
  m.info.cv_accuracy = r.get<double>();
  m.info.description = r.get_string();
  if (r.version() >= 5) {
    m.calibration.a = r.get<double>();
    m.calibration.b = r.get<double>();
    m.calibration.examples = r.get<std::uint64_t>();
  }
  if (r.version() >= 6) {
    const auto probability = r.get<std::uint8_t>();
    if (probability > 1) r.fail("inconsistent: score kind " + std::to_string(probability));
    m.operating.probability = probability == 1;
    m.operating.accept = r.get<double>();
    m.operating.relaxed = r.get<double>();
  }
  r.expect_end();
  const std::size_t d = m.input_dimension();
  if (basis.codes.size() != m.components() * d) {
    r.fail("inconsistent: PCA basis size disagrees with its components");
  }
  m.basis.resize(basis.codes.size());
  decode_runs(
      basis, m.components(), d, 1, [&](std::size_t j) { return m.basis.data() + j * d; }, r);
  m.support_vectors = decode_support_vectors(m, halves, coded, r);
  const std::string problem = model_problem(m);
  if (!problem.empty()) r.fail("inconsistent: " + problem);
  return m;
}

}  // namespace antipode
