#pragma once
/// @file
/// Training and evaluating the paper's hand classifier (section 4.3): PCA-reduced HOG
/// descriptors (one common scale, not whitened), a polynomial-kernel soft-margin SVM whose
/// C (and gamma) are chosen by grouped k-fold cross-validation. The solver is antipode's
/// (svm_solver.hpp); the result is an SvmModel. Everything is
/// deterministic: the same training set and options give a bit-identical model, whatever the
/// thread count.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "antipode/core/hand_geometry.hpp"
#include "antipode/grasp/hand_image.hpp"
#include "antipode/grasp/svm_model.hpp"
#include "antipode/grasp/training_set.hpp"

namespace antipode {

/// Called as work finishes: `done` of `total` steps, and what was just done.
using SvmProgress =
    std::function<void(std::size_t done, std::size_t total, const std::string& step)>;

/// What a cross-validation fold keeps together.
enum class FoldUnit {
  kExample,  ///< nothing: every example on its own (the paper's random folds)
  kHand,     ///< a hand's descriptors (TrainingSet::groups: its C1, C2 and C12 images)
  kScene,    ///< every example of one scene (TrainingSet::sources): whole objects held out
};

/// The unit named "example", "hand" or "scene"; another word is an antipode::Error that
/// lists them.
FoldUnit fold_unit(const std::string& name);

struct SvmTrainingOptions {
  /// Kernel families tried by cross-validation (the paper compared Gaussian and polynomial
  /// kernels and chose the degree-3 polynomial).
  std::vector<SvmKernelType> kernels = {SvmKernelType::kPolynomial};
  int degree = 3;                                    ///< polynomial degree (the paper: 3)
  double coef0 = 1.0;                                ///< kernel (gamma a . b + coef0)^degree
  std::vector<double> c_values = {0.1, 1, 10, 100};  ///< C candidates
  /// gamma candidates; empty means the single value 1 / components (the reduced features
  /// have unit variance on average, so gamma a . b and gamma |a - b|^2 / 2 are of order one).
  std::vector<double> gamma_values;
  std::size_t pca_components = 96;      ///< k (fewer when the data has lower rank)
  std::size_t max_pca_examples = 6000;  ///< PCA is fitted on a seeded subsample this large
  int folds = 10;                       ///< cross-validation folds; 0 skips cross-validation
  FoldUnit folds_by = FoldUnit::kHand;  ///< what a fold keeps together
  std::uint64_t seed = 0;               ///< fold assignment and PCA subsample
  int threads = 0;                      ///< workers (0: all); results do not depend on it
  double tolerance = 1e-3;              ///< solver stopping tolerance (as libsvm's eps)
  int max_iterations = 10000000;        ///< solver iteration cap
  std::size_t cache_mib = 1024;         ///< kernel row cache per solver (svm_solver.hpp)
  double positive_weight = 1.0;         ///< C of grasps / C of non-grasps (svm_solver.hpp)
  std::string description;              ///< copied into the model's info
  SvmProgress progress;  ///< optional; called from worker threads, one call at a time

  /// Throws antipode::Error naming the first invalid field.
  void validate() const;
};

/// Binary classification counts, positive = a grasp.
struct ConfusionMatrix {
  std::uint64_t tp = 0;  ///< grasps classified as grasps
  std::uint64_t fp = 0;  ///< non-grasps classified as grasps
  std::uint64_t tn = 0;  ///< non-grasps classified as non-grasps
  std::uint64_t fn = 0;  ///< grasps classified as non-grasps

  std::uint64_t total() const { return tp + fp + tn + fn; }
  double accuracy() const;   ///< (tp + tn) / total, 0 when empty
  double precision() const;  ///< tp / (tp + fp), 0 when nothing was called a grasp
  double recall() const;     ///< tp / (tp + fn), 0 when there are no grasps
  ConfusionMatrix& operator+=(const ConfusionMatrix& other);
};

/// The cross-validation of one (kernel, C, gamma) candidate.
struct CrossValidationPoint {
  double C = 0.0;
  double gamma = 0.0;
  SvmKernelType kernel = SvmKernelType::kPolynomial;
  ConfusionMatrix confusion;  ///< summed over the folds (each example held out once)
};

struct CrossValidationResult {
  /// One per candidate, in grid order: kernel, then C, then gamma.
  std::vector<CrossValidationPoint> points;
  std::size_t best = 0;  ///< index of the most accurate (first on ties)
  int folds = 0;

  const CrossValidationPoint& best_point() const { return points.at(best); }
  double accuracy() const { return best_point().confusion.accuracy(); }
};

/// Fold (0..folds-1) of every example: whole units (hands, scenes or single examples, as
/// `unit` says) are dealt round-robin to folds in a seeded shuffled order, so no unit
/// straddles training and held-out data. Throws antipode::Error when there are fewer units
/// than folds.
std::vector<int> assign_folds(const TrainingSet& set, int folds, std::uint64_t seed,
                              FoldUnit unit = FoldUnit::kHand);

/// k-fold cross-validation, folds by `options.folds_by`, of every (kernel, C, gamma) candidate (PCA
/// fitted once on the whole set, as train_svm() does). `options.folds` must be at least 2.
CrossValidationResult cross_validate(const TrainingSet& set, const SvmTrainingOptions& options);

/// Fits the PCA reduction, chooses kernel, C and gamma by grouped cross-validation (the first
/// candidate when `options.folds` is 0; the chosen accuracy goes to info.cv_accuracy), then
/// trains on the whole set. The model records `image` and `geometry` as its descriptor spec.
/// Throws antipode::Error for an empty set, a set with one class only, descriptors whose
/// length is not `image`'s descriptor size, or a set whose recorded descriptor options and
/// hand (TrainingSet::descriptor, ::geometry) differ from `image` and `geometry`.
SvmModel train_svm(const TrainingSet& set, const SvmTrainingOptions& options,
                   const HandImageOptions& image, const HandGeometry& geometry);

/// The same, for the descriptor options and hand the training set records.
SvmModel train_svm(const TrainingSet& set, const SvmTrainingOptions& options);

/// The confusion matrix of decision values against labels (+1 a grasp): values at or above
/// `threshold` are called grasps. Throws antipode::Error when the lengths differ.
ConfusionMatrix confusion(const std::vector<double>& values, const std::vector<std::int8_t>& labels,
                          double threshold = 0.0);

/// Classifies every example of `set` with `model` (positive when the decision value is
/// >= `threshold`) and counts the outcomes.
ConfusionMatrix evaluate(const SvmModel& model, const TrainingSet& set, int threads = 0,
                         double threshold = 0.0);

}  // namespace antipode
