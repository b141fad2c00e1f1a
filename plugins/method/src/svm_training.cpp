#include "antipode/grasp/svm_training.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numeric>
#include <sstream>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include "antipode/core/error.hpp"
#include "antipode/core/random.hpp"
#include "antipode/grasp/svm_solver.hpp"

namespace antipode {
namespace {

using RowMatrixF = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using MatrixF = Eigen::MatrixXf;

constexpr int kPowerIterations = 4;

std::string number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}
constexpr std::size_t kOversampling = 16;

// ---------------------------------------------------------------------------------------
// Input checks.

void check_training_set(const TrainingSet& set) {
  set.validate();
  if (set.empty()) throw Error("SVM training: the training set is empty");
  const std::size_t positives = set.positives();
  if (positives == 0 || positives == set.size()) {
    throw Error("SVM training: the training set has only " +
                std::string(positives == 0 ? "negative" : "positive") + " examples (" +
                std::to_string(set.size()) + "); the SVM needs both grasps and non-grasps");
  }
}

// ---------------------------------------------------------------------------------------
// Progress, reported one call at a time from any worker.

class ProgressReporter {
 public:
  ProgressReporter(const SvmProgress& callback, std::size_t total)
      : callback_(callback), total_(total) {}
  void step(const std::string& what) {
    if (!callback_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    callback_(++done_, total_, what);
  }

 private:
  const SvmProgress& callback_;
  std::size_t total_;
  std::size_t done_ = 0;
  std::mutex mutex_;
};

// ---------------------------------------------------------------------------------------
// PCA: randomized subspace iteration on a seeded subsample (deterministic, and far cheaper
// than an eigen-decomposition of the full covariance).

std::vector<float> column_mean(const TrainingSet& set) {
  std::vector<double> sum(set.dimension, 0.0);
  for (std::size_t i = 0; i < set.size(); ++i) {
    const float* row = set.row(i);
    for (std::size_t c = 0; c < set.dimension; ++c) sum[c] += row[c];
  }
  std::vector<float> mean(set.dimension);
  for (std::size_t c = 0; c < set.dimension; ++c) {
    mean[c] = static_cast<float>(sum[c] / static_cast<double>(set.size()));
  }
  return mean;
}

std::vector<std::size_t> pca_sample(std::size_t n, std::size_t max_rows, std::uint64_t seed) {
  std::vector<std::size_t> indices(n);
  std::iota(indices.begin(), indices.end(), 0);
  if (n <= max_rows) return indices;
  RandomStream random = RandomStream(seed).derive(1);
  for (std::size_t i = 0; i < max_rows; ++i) {  // partial Fisher-Yates
    std::swap(indices[i], indices[i + random.below(n - i)]);
  }
  indices.resize(max_rows);
  std::sort(indices.begin(), indices.end());
  return indices;
}

RowMatrixF centred_rows(const TrainingSet& set, const std::vector<std::size_t>& indices,
                        const std::vector<float>& mean) {
  RowMatrixF a(static_cast<Eigen::Index>(indices.size()), static_cast<Eigen::Index>(set.dimension));
  for (std::size_t r = 0; r < indices.size(); ++r) {
    const float* row = set.row(indices[r]);
    for (std::size_t c = 0; c < set.dimension; ++c) {
      a(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = row[c] - mean[c];
    }
  }
  return a;
}

MatrixF orthonormal_columns(const MatrixF& y) {
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(y.cast<double>());
  const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(y.rows(), y.cols());
  return q.cast<float>();
}

// Fills model.basis and model.scale with the top `wanted` principal directions of `a`. All
// components share one scale, 1 / the root mean square of their standard deviations, so the
// reduced descriptors keep the PCA's proportions (a component's weight in the kernel is its
// variance) at unit variance per component on average. Whitening each component to unit
// variance instead gave the many weak components (mostly HOG detail) as much say as the
// leading ones: 94.2% against 95.1% hand-grouped cross-validation on the 100-scene training
// set, 91.7% against 93.0% on novel objects (docs/results.md), and it made the descriptor's
// weights (hand_image.cpp) matter.
void principal_components(const RowMatrixF& a, std::size_t wanted, std::uint64_t seed,
                          SvmModel& model) {
  const Eigen::Index d = a.cols();
  const auto width = static_cast<Eigen::Index>(std::min<std::size_t>(
      {wanted + kOversampling, static_cast<std::size_t>(a.rows()), static_cast<std::size_t>(d)}));
  RandomStream random = RandomStream(seed).derive(2);
  MatrixF q(d, width);
  for (Eigen::Index c = 0; c < width; ++c) {
    for (Eigen::Index r = 0; r < d; ++r) q(r, c) = static_cast<float>(random.normal());
  }
  q = orthonormal_columns(q);
  for (int i = 0; i < kPowerIterations; ++i) {
    const MatrixF z = a * q;
    q = orthonormal_columns(a.transpose() * z);
  }
  const MatrixF b = a * q;
  const Eigen::MatrixXd gram = (b.transpose() * b).cast<double>();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram);
  const Eigen::VectorXd& values = eigen.eigenvalues();  // ascending
  const double largest = std::max(values(width - 1), 0.0);
  const double samples = std::max<double>(static_cast<double>(a.rows()) - 1.0, 1.0);
  model.basis.clear();
  std::size_t kept = 0;
  double variance_sum = 0.0;
  for (Eigen::Index j = width - 1; j >= 0 && kept < wanted; --j) {
    if (!(values(j) > 1e-10 * largest) || largest <= 0.0) break;
    Eigen::VectorXd direction = q.cast<double>() * eigen.eigenvectors().col(j);
    direction.normalize();
    Eigen::Index peak = 0;
    direction.cwiseAbs().maxCoeff(&peak);
    if (direction(peak) < 0.0) direction = -direction;  // a canonical sign
    for (Eigen::Index c = 0; c < d; ++c) model.basis.push_back(static_cast<float>(direction(c)));
    variance_sum += values(j) / samples;
    ++kept;
  }
  if (kept == 0) {
    throw Error("SVM training: all training descriptors are identical; nothing to learn");
  }
  const double mean_variance = variance_sum / static_cast<double>(kept);
  model.scale.assign(kept, static_cast<float>(1.0 / std::sqrt(mean_variance)));
}

// A model holding only the reduction (mean, basis, scale) fitted to `set`.
SvmModel fit_reduction(const TrainingSet& set, const SvmTrainingOptions& options) {
  SvmModel model;
  model.mean = column_mean(set);
  const auto sample = pca_sample(set.size(), options.max_pca_examples, options.seed);
  principal_components(centred_rows(set, sample, model.mean), options.pca_components, options.seed,
                       model);
  model.round_basis();  // as the model file stores it
  return model;
}

// ---------------------------------------------------------------------------------------
// The SVM solver (svm_solver.hpp), on reduced features.

struct SvmSolution {
  std::vector<float> support_vectors;
  std::vector<double> alpha;
  double rho = 0.0;
};

struct ReducedSet {
  std::vector<float> z;  // n x k
  std::size_t k = 0;
  const std::vector<std::int8_t>* labels = nullptr;
};

// Trains on `rows` of `data` with `threads` kernel row workers; the support vectors are the
// rows with a positive multiplier, their coefficients y_t a_t (positive for grasps).
SvmSolution solve(const ReducedSet& data, const std::vector<std::size_t>& rows,
                  const SvmKernel& kernel, const SvmTrainingOptions& options, int threads) {
  std::vector<float> z(rows.size() * data.k);
  std::vector<std::int8_t> labels(rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    std::copy_n(data.z.data() + rows[r] * data.k, data.k, z.data() + r * data.k);
    labels[r] = (*data.labels)[rows[r]];
  }
  SvmSolverOptions solver;
  solver.tolerance = options.tolerance;
  solver.max_iterations = options.max_iterations;
  solver.cache_mib = options.cache_mib;
  solver.positive_weight = options.positive_weight;
  solver.threads = threads;
  const SvmDualSolution dual =
      solve_svm_dual(z.data(), rows.size(), data.k, labels, kernel, solver);
  SvmSolution s;
  s.rho = dual.rho;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (dual.alpha[r] <= 0.0) continue;
    s.alpha.push_back(labels[r] > 0 ? dual.alpha[r] : -dual.alpha[r]);
    const float* row = z.data() + r * data.k;
    s.support_vectors.insert(s.support_vectors.end(), row, row + data.k);
  }
  return s;
}

void install(const SvmSolution& solution, const SvmKernel& kernel, SvmModel& model) {
  model.kernel = kernel;
  model.support_vectors = solution.support_vectors;
  model.alpha = solution.alpha;
  model.round_support_vectors();  // as the model file stores them
  model.rho = solution.rho;
}

// ---------------------------------------------------------------------------------------
// Cross-validation.

std::vector<SvmKernel> candidates(const SvmTrainingOptions& o, std::size_t components) {
  std::vector<double> gammas = o.gamma_values;
  if (gammas.empty()) gammas.push_back(1.0 / static_cast<double>(components));
  std::vector<SvmKernel> kernels;
  for (const SvmKernelType type : o.kernels) {
    for (const double c : o.c_values) {
      for (const double gamma : gammas) {
        kernels.push_back(SvmKernel{type, o.degree, gamma, o.coef0, c});
      }
    }
  }
  return kernels;
}

// "poly C=0.3 gamma=0.0104" or "rbf C=3 gamma=0.01".
std::string describe(const SvmKernel& kernel) {
  return std::string(kernel_name(kernel.type)) + " C=" + number(kernel.C) +
         " gamma=" + number(kernel.gamma);
}

bool has_both_classes(const std::vector<std::int8_t>& labels,
                      const std::vector<std::size_t>& rows) {
  bool positive = false;
  bool negative = false;
  for (const std::size_t r : rows) (labels[r] > 0 ? positive : negative) = true;
  return positive && negative;
}

ConfusionMatrix count(const std::vector<double>& values, const std::vector<std::int8_t>& labels,
                      const std::vector<std::size_t>& rows, double threshold) {
  ConfusionMatrix m;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const bool grasp = labels[rows[i]] > 0;
    const bool called = values[i] >= threshold;
    ++(grasp ? (called ? m.tp : m.fn) : (called ? m.fp : m.tn));
  }
  return m;
}

ConfusionMatrix run_fold(const SvmModel& reduction, const ReducedSet& data,
                         const std::vector<int>& fold_of, int fold, const SvmKernel& kernel,
                         const SvmTrainingOptions& options) {
  std::vector<std::size_t> train;
  std::vector<std::size_t> held_out;
  for (std::size_t i = 0; i < fold_of.size(); ++i) {
    (fold_of[i] == fold ? held_out : train).push_back(i);
  }
  if (!has_both_classes(*data.labels, train)) {
    throw Error("SVM cross-validation: the training part of fold " + std::to_string(fold + 1) +
                " holds one class only; use fewer folds or more varied data");
  }
  SvmModel model = reduction;
  install(solve(data, train, kernel, options, 1), kernel, model);
  std::vector<float> z;
  z.reserve(held_out.size() * data.k);
  for (const std::size_t i : held_out) {
    const float* row = data.z.data() + i * data.k;
    z.insert(z.end(), row, row + data.k);
  }
  return count(model.decision_values_reduced(z.data(), held_out.size(), 1), *data.labels, held_out,
               0.0);
}

CrossValidationResult cross_validate_reduced(const TrainingSet& set, const SvmModel& reduction,
                                             const ReducedSet& data,
                                             const SvmTrainingOptions& options,
                                             ProgressReporter& progress) {
  const std::vector<int> fold_of = assign_folds(set, options.folds, options.seed, options.folds_by);
  const std::vector<SvmKernel> kernels = candidates(options, reduction.components());
  const std::size_t folds = static_cast<std::size_t>(options.folds);
  std::vector<ConfusionMatrix> results(kernels.size() * folds);
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, results.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t t = range.begin(); t != range.end(); ++t) {
                          const SvmKernel& kernel = kernels[t / folds];
                          results[t] = run_fold(reduction, data, fold_of,
                                                static_cast<int>(t % folds), kernel, options);
                          progress.step("cross-validation " + describe(kernel) + " fold " +
                                        std::to_string(t % folds + 1));
                        }
                      });
  });
  CrossValidationResult result;
  result.folds = options.folds;
  for (std::size_t p = 0; p < kernels.size(); ++p) {
    CrossValidationPoint point{kernels[p].C, kernels[p].gamma, kernels[p].type, {}};
    for (std::size_t f = 0; f < folds; ++f) point.confusion += results[p * folds + f];
    result.points.push_back(point);
    if (point.confusion.accuracy() > result.points[result.best].confusion.accuracy()) {
      result.best = p;
    }
  }
  return result;
}

ReducedSet reduce_all(const TrainingSet& set, const SvmModel& reduction, int threads) {
  ReducedSet data;
  data.k = reduction.components();
  data.z = reduction.reduce(set.features.data(), set.size(), set.dimension, threads);
  data.labels = &set.labels;
  return data;
}

std::size_t steps(const SvmTrainingOptions& o, bool with_cv) {
  const std::size_t grid = o.kernels.size() * o.c_values.size() *
                           std::max<std::size_t>(o.gamma_values.size(), std::size_t{1});
  return 2 + (with_cv ? grid * static_cast<std::size_t>(o.folds) : 0);
}

}  // namespace

// -----------------------------------------------------------------------------------------

void SvmTrainingOptions::validate() const {
  const auto fail = [](const std::string& what) { throw Error("SVM training options: " + what); };
  if (kernels.empty()) fail("no kernel candidates");
  if (degree < 1 || degree > 10) fail("degree must be in [1, 10], got " + std::to_string(degree));
  if (!std::isfinite(coef0)) fail("coef0 must be finite");
  if (c_values.empty()) fail("no C candidates");
  for (const double c : c_values) {
    if (!(std::isfinite(c) && c > 0.0)) fail("C candidates must be positive");
  }
  for (const double g : gamma_values) {
    if (!(std::isfinite(g) && g > 0.0)) fail("gamma candidates must be positive");
  }
  if (pca_components < 1) fail("pca_components must be at least 1");
  if (max_pca_examples < 2) fail("max_pca_examples must be at least 2");
  if (folds < 0 || folds == 1) fail("folds must be 0 (no cross-validation) or at least 2");
  if (threads < 0) fail("threads must be >= 0");
  if (!(tolerance > 0.0 && std::isfinite(tolerance))) fail("tolerance must be positive");
  if (max_iterations < 1) fail("max_iterations must be at least 1");
  if (!(positive_weight > 0.0 && std::isfinite(positive_weight))) {
    fail("positive_weight must be positive");
  }
}

double ConfusionMatrix::accuracy() const {
  return total() == 0 ? 0.0 : static_cast<double>(tp + tn) / static_cast<double>(total());
}

double ConfusionMatrix::precision() const {
  return tp + fp == 0 ? 0.0 : static_cast<double>(tp) / static_cast<double>(tp + fp);
}

double ConfusionMatrix::recall() const {
  return tp + fn == 0 ? 0.0 : static_cast<double>(tp) / static_cast<double>(tp + fn);
}

ConfusionMatrix& ConfusionMatrix::operator+=(const ConfusionMatrix& o) {
  tp += o.tp;
  fp += o.fp;
  tn += o.tn;
  fn += o.fn;
  return *this;
}

FoldUnit fold_unit(const std::string& name) {
  if (name == "example") return FoldUnit::kExample;
  if (name == "hand") return FoldUnit::kHand;
  if (name == "scene") return FoldUnit::kScene;
  throw Error("folds by '" + name + "': expected example, hand or scene");
}

std::vector<int> assign_folds(const TrainingSet& set, int folds, std::uint64_t seed,
                              FoldUnit unit) {
  if (folds < 1) throw Error("cross-validation: folds must be at least 1");
  std::vector<std::int32_t> unit_of(set.size());
  for (std::size_t i = 0; i < set.size(); ++i) {
    unit_of[i] = unit == FoldUnit::kExample ? static_cast<std::int32_t>(i)
                 : unit == FoldUnit::kHand  ? set.groups[i]
                                            : set.sources[i];
  }
  std::vector<std::int32_t> groups = unit_of;
  std::sort(groups.begin(), groups.end());
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  if (groups.size() < static_cast<std::size_t>(folds)) {
    const char* what = unit == FoldUnit::kExample ? "examples"
                       : unit == FoldUnit::kHand  ? "hands"
                                                  : "scenes (distinct sources)";
    throw Error("cross-validation: " + std::to_string(folds) + " folds need at least " +
                std::to_string(folds) + " " + what + ", the training set has " +
                std::to_string(groups.size()));
  }
  RandomStream random = RandomStream(seed).derive(0);
  for (std::size_t i = groups.size(); i > 1; --i) {
    std::swap(groups[i - 1], groups[random.below(i)]);
  }
  std::vector<std::pair<std::int32_t, int>> fold_of_group;
  for (std::size_t i = 0; i < groups.size(); ++i) {
    fold_of_group.emplace_back(groups[i], static_cast<int>(i % static_cast<std::size_t>(folds)));
  }
  std::sort(fold_of_group.begin(), fold_of_group.end());
  std::vector<int> fold_of(set.size());
  for (std::size_t i = 0; i < set.size(); ++i) {
    const auto it =
        std::lower_bound(fold_of_group.begin(), fold_of_group.end(), std::make_pair(unit_of[i], 0));
    fold_of[i] = it->second;
  }
  return fold_of;
}

CrossValidationResult cross_validate(const TrainingSet& set, const SvmTrainingOptions& options) {
  options.validate();
  check_training_set(set);
  if (options.folds < 2) throw Error("cross-validation: folds must be at least 2");
  ProgressReporter progress(options.progress, steps(options, true));
  const SvmModel reduction = fit_reduction(set, options);
  progress.step("PCA");
  const ReducedSet data = reduce_all(set, reduction, options.threads);
  return cross_validate_reduced(set, reduction, data, options, progress);
}

SvmModel train_svm(const TrainingSet& set, const SvmTrainingOptions& options,
                   const HandImageOptions& image, const HandGeometry& geometry) {
  options.validate();
  image.validate();
  geometry.validate();
  check_training_set(set);
  if (set.dimension != image.descriptor_size()) {
    throw Error("SVM training: the training set's descriptors have " +
                std::to_string(set.dimension) + " numbers, but " +
                SvmDescriptorSpec::of(image, geometry).describe() + " gives " +
                std::to_string(image.descriptor_size()));
  }
  const SvmDescriptorSpec recorded = SvmDescriptorSpec::of(set.descriptor, set.geometry);
  if (!recorded.matches(SvmDescriptorSpec::of(image, geometry))) {
    throw Error("SVM training: the training set's descriptors were computed for " +
                recorded.describe() + ", not " + SvmDescriptorSpec::of(image, geometry).describe());
  }
  const bool with_cv = options.folds >= 2;
  ProgressReporter progress(options.progress, steps(options, with_cv));
  SvmModel model = fit_reduction(set, options);
  progress.step("PCA");
  const ReducedSet data = reduce_all(set, model, options.threads);
  SvmKernel kernel = candidates(options, model.components()).front();
  model.info.cv_accuracy = -1.0;
  if (with_cv) {
    const CrossValidationResult cv = cross_validate_reduced(set, model, data, options, progress);
    kernel.type = cv.best_point().kernel;
    kernel.C = cv.best_point().C;
    kernel.gamma = cv.best_point().gamma;
    model.info.cv_accuracy = cv.accuracy();
  }
  std::vector<std::size_t> all(set.size());
  std::iota(all.begin(), all.end(), 0);
  install(solve(data, all, kernel, options, options.threads), kernel, model);
  progress.step("final training");
  model.descriptor = SvmDescriptorSpec::of(image, geometry);
  model.info.positives = set.positives();
  model.info.negatives = set.negatives();
  model.info.seed = options.seed;
  model.info.description = options.description;
  model.validate("SVM training");
  return model;
}

SvmModel train_svm(const TrainingSet& set, const SvmTrainingOptions& options) {
  return train_svm(set, options, set.descriptor, set.geometry);
}

ConfusionMatrix evaluate(const SvmModel& model, const TrainingSet& set, int threads,
                         double threshold) {
  set.validate();
  if (set.empty()) return {};
  const std::vector<double> values =
      model.decision_values(set.features.data(), set.size(), set.dimension, threads);
  return confusion(values, set.labels, threshold);
}

ConfusionMatrix confusion(const std::vector<double>& values, const std::vector<std::int8_t>& labels,
                          double threshold) {
  if (values.size() != labels.size()) {
    throw Error("confusion matrix: " + std::to_string(values.size()) + " values but " +
                std::to_string(labels.size()) + " labels");
  }
  std::vector<std::size_t> all(values.size());
  std::iota(all.begin(), all.end(), 0);
  return count(values, labels, all, threshold);
}

}  // namespace antipode
