#pragma once
/// @file
/// A trained hand classifier (paper section 4): everything needed to turn HOG descriptors of
/// grasp hypothesis images into decision values, without OpenCV. A descriptor x (the
/// `descriptor.image` layout, `input_dimension()` numbers) is
///
///   1. reduced:  z_j = scale_j * basis_j . (x - mean)          (j < components(); PCA)
///   2. scored:   f(x) = sum_i alpha_i K(z, sv_i) - rho
///
/// with the polynomial kernel K(a, b) = (gamma a . b + coef0)^degree (the paper's) or the
/// Gaussian (RBF) kernel K(a, b) = exp(-gamma |a - b|^2). f > 0 means "a grasp" (the
/// label-+1 side of the SVM); higher is more confident. Models are written by train_svm()
/// (svm_training.hpp) and stored with save() in antipode's binary container
/// (core/binary_file.hpp).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "antipode/core/hand_geometry.hpp"
#include "antipode/grasp/calibration.hpp"
#include "antipode/grasp/hand_image.hpp"

namespace antipode {

/// What produced the descriptors a model was trained on. Two descriptor setups are
/// compatible when the name, the image options and the three hand lengths agree.
struct SvmDescriptorSpec {
  std::string name = "occupancy-hog-5";  ///< descriptor algorithm and its version
  HandImageOptions image;                ///< image layout and HOG parameters
  double depth_m = 0.06;                 ///< finger depth the image spans (rows)
  double max_aperture_m = 0.072;         ///< aperture the image spans (columns)
  double height_m = 0.02;                ///< hand height: the closing region's thickness

  /// The spec of descriptors computed with `image` for a hand of `geometry`.
  static SvmDescriptorSpec of(const HandImageOptions& image, const HandGeometry& geometry);
  /// "a 0.06 m deep, 0.072 m wide, 0.02 m high hand with 10 x 12 HOG cells of 6 px (2 x 2
  /// cell blocks, 9 bins, ..., occupancy-hog-5)".
  std::string describe() const;
  /// Same name and image options, and hand lengths within 1e-9 m.
  bool matches(const SvmDescriptorSpec& other) const;
};

/// The kernel families a model can use.
enum class SvmKernelType {
  kPolynomial,  ///< K(a, b) = (gamma a . b + coef0)^degree ("poly")
  kRbf,         ///< K(a, b) = exp(-gamma |a - b|^2) ("rbf"; degree and coef0 unused)
};

/// "poly" or "rbf".
const char* kernel_name(SvmKernelType type);
/// The kernel named "poly" or "rbf"; another word is an antipode::Error that lists them.
SvmKernelType kernel_type(const std::string& name);

/// The kernel and the soft-margin cost C the machine was trained with.
struct SvmKernel {
  SvmKernelType type = SvmKernelType::kPolynomial;
  int degree = 3;
  double gamma = 1.0;
  double coef0 = 1.0;
  double C = 1.0;  ///< recorded for reference; prediction does not use it
};

/// Facts about the training run, stored with the model for reports.
struct SvmTrainingInfo {
  std::uint64_t positives = 0;  ///< training examples labelled +1
  std::uint64_t negatives = 0;  ///< training examples labelled -1
  std::uint64_t seed = 0;       ///< seed of the fold assignment and PCA subsample
  /// Grouped k-fold cross-validation accuracy of the chosen parameters in [0, 1]; negative
  /// when no cross-validation was run.
  double cv_accuracy = -1.0;
  std::string description;  ///< free text (training data, command line, ...)
};

/// How a model's scores are read and the thresholds it is meant to be used at: its operating
/// points, chosen when it was made (on training scenes, docs/training.md) and stored in its
/// file, so that a tree names only the model. `hog_svm_classifier` takes its `score` and
/// `threshold` defaults from here. Files of formats 4 and 5 load with the defaults below.
struct SvmOperatingPoints {
  /// true: hands are scored by their calibrated probability of success (the model must be
  /// calibrated); false: by the SVM's decision value.
  bool probability = false;
  double accept = 0.0;    ///< hands scoring at least this are grasps
  double relaxed = -0.5;  ///< a second chance's lower threshold (trees/clear_box.yaml); <= accept
};

class SvmModel {
 public:
  SvmDescriptorSpec descriptor;
  /// Reduction: `mean` (input_dimension()), `basis` (components() x input_dimension(),
  /// row-major, orthonormal rows) and `scale` (components(): the factor each component is
  /// multiplied by; train_svm() gives them all 1 / the root mean square of the components'
  /// standard deviations on the training data). Model files store each basis row as 8-bit
  /// codes c * 2^e (|c| <= 127, one power-of-two step per row); train_svm() rounds it so
  /// (round_basis()) before reducing the training data.
  std::vector<float> mean;
  std::vector<float> basis;
  std::vector<float> scale;
  SvmKernel kernel;
  /// Support vectors in reduced space: support_vector_count() x components(), row-major.
  /// Model files store component j < kHalfPrecisionComponents at half precision (IEEE
  /// binary16: 11 significant bits, at most 65504 in magnitude) and every later component as
  /// 8-bit codes c * 2^e_j (|c| <= 127, one power-of-two step per component: 7 significant
  /// bits of the component's largest number). train_svm() rounds them so
  /// (round_support_vectors()), so a trained model, its cross-validation folds and the model
  /// loaded from its file all give the same decision values.
  std::vector<float> support_vectors;
  std::vector<double> alpha;  ///< dual coefficient of each support vector (label sign included)
  double rho = 0.0;           ///< offset subtracted from the kernel sum
  SvmTrainingInfo info;
  /// Maps decision values to probabilities of success; not fitted() unless the model was
  /// calibrated on held-out outcomes (calibration.hpp, `CalibrateClassifier`). Files of
  /// format 4, from before calibration, load uncalibrated.
  PlattScaling calibration;
  /// How the classifier reads the scores by default (format 6; older files: decision values,
  /// 0 and -0.5).
  SvmOperatingPoints operating;

  std::size_t input_dimension() const { return mean.size(); }
  std::size_t components() const { return scale.size(); }
  std::size_t support_vector_count() const { return alpha.size(); }

  /// Throws antipode::Error (prefixed with `context`, e.g. the file name) when the sizes
  /// disagree with each other or with the descriptor options, a number is non-finite, a
  /// polynomial kernel's degree is outside [1, 10], the model has no support vector, or the
  /// operating points are not finite, relaxed exceeds accept, or they are probabilities of an
  /// uncalibrated model or outside [0, 1].
  void validate(const std::string& context = "SVM model") const;

  /// Decision values f(x) of `n` row-major descriptors of `dim` numbers at `rows`, using
  /// `threads` workers (0: all). Rows are processed in fixed blocks of kBlockRows (the last
  /// one zero-padded) with matrix products, so memory stays bounded and every value is the
  /// same whatever the thread count. Throws antipode::Error when `dim` is not
  /// input_dimension().
  std::vector<double> decision_values(const float* rows, std::size_t n, std::size_t dim,
                                      int threads = 0) const;
  /// The same for descriptors held one per vector (as hand_descriptors() returns them).
  std::vector<double> decision_values(const std::vector<std::vector<float>>& descriptors,
                                      int threads = 0) const;

  /// The reduced features z (n x components(), row-major) of `n` descriptors, computed as
  /// in decision_values(); training uses it so that both share one code path.
  std::vector<float> reduce(const float* rows, std::size_t n, std::size_t dim,
                            int threads = 0) const;
  /// Decision values of already reduced rows (n x components(), row-major).
  std::vector<double> decision_values_reduced(const float* reduced, std::size_t n,
                                              int threads = 0) const;

  /// Throws antipode::Error "<model_name> was trained for <spec>; this hand set has <spec>
  /// (retrain with `antipode train`)" unless descriptors of `image` for `geometry` match
  /// the model's.
  void check_compatible(const HandImageOptions& image, const HandGeometry& geometry,
                        const std::string& model_name = "the SVM model") const;

  /// Rounds every support vector number to the nearest number the model file can hold (see
  /// support_vectors); rounding twice changes nothing. Throws antipode::Error for a
  /// half-precision number beyond its range.
  void round_support_vectors();
  /// Rounds every basis number to the nearest number the model file can hold (see basis);
  /// rounding twice changes nothing. Throws antipode::Error for a basis of the wrong size or
  /// with a non-finite number.
  void round_basis();

  /// Writes the model to `path` all-or-nothing (validated first); the bytes depend only on
  /// the model's contents. The basis and support vectors are written as described above
  /// (rounded to nearest); the rest at full precision.
  void save(const std::string& path) const;
  /// Reads a file written by save(). A missing, truncated, corrupted, foreign or
  /// inconsistent file is an antipode::Error naming the file and the problem.
  static SvmModel load(const std::string& path);

  static constexpr std::size_t kBlockRows = 128;
  /// Support vector components stored at half precision; the rest are 8-bit codes.
  static constexpr std::size_t kHalfPrecisionComponents = 16;
};

}  // namespace antipode
