#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/ml.hpp>

#include "antipode/core/binary_file.hpp"
#include "antipode/core/error.hpp"
#include "antipode/core/random.hpp"
#include "antipode/geometry/sample_hands.hpp"
#include "antipode/grasp/antipodal.hpp"
#include "antipode/grasp/hand_image.hpp"
#include "antipode/grasp/svm_model.hpp"
#include "antipode/grasp/svm_training.hpp"
#include "antipode/grasp/training_set.hpp"
#include "antipode/io/load_cloud.hpp"
#include "support/error_of.hpp"
#include "support/toy_hands.hpp"

namespace antipode {
namespace {

namespace fs = std::filesystem;
using testing::error_of;

// The descriptors (default options, default hand) of toy hands.
std::vector<std::vector<float>> toy_descriptors(const std::vector<bool>& positive,
                                                RandomStream& random) {
  return hand_descriptors(testing::toy_hand_set(positive, random), HandGeometry{},
                          HandImageOptions{}, 2);
}

// `hands` hands of three descriptors each (as C1, C2, C12), about half of them positive.
TrainingSet toy_set(std::size_t hands, std::uint64_t seed) {
  RandomStream random(seed);
  std::vector<bool> positive;
  for (std::size_t h = 0; h < hands; ++h) positive.push_back(random.uniform() < 0.5);
  std::vector<bool> examples;
  for (const bool p : positive) examples.insert(examples.end(), 3, p);
  const auto descriptors = toy_descriptors(examples, random);
  TrainingSet set;
  for (std::size_t i = 0; i < descriptors.size(); ++i) {
    const auto hand = static_cast<std::int32_t>(i / 3);
    set.add(descriptors[i], examples[i], hand, hand % 7);
  }
  return set;
}

SvmTrainingOptions small_options() {
  SvmTrainingOptions o;
  o.pca_components = 24;
  o.c_values = {1.0, 10.0};
  o.folds = 3;
  o.seed = 5;
  o.threads = 2;
  return o;
}

const TrainingSet& training() {
  static const TrainingSet set = toy_set(80, 1);
  return set;
}

const TrainingSet& held_out() {
  static const TrainingSet set = toy_set(60, 2);
  return set;
}

const SvmModel& trained() {
  static const SvmModel model =
      train_svm(training(), small_options(), HandImageOptions{}, HandGeometry{});
  return model;
}

std::string temp_path(const std::string& name) {
  return (fs::temp_directory_path() / ("antipode_svm_test_" + name)).string();
}

std::vector<char> bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void write_bytes(const std::string& path, const std::vector<char>& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// Header: magic (8), version (4), payload size (8), FNV-1a 64 of the payload (8).
constexpr std::size_t kHeaderBytes = 28;

// Rewrites the checksum so that an edited payload passes the container's check.
void fix_checksum(std::vector<char>& bytes) {
  std::uint64_t hash = 14695981039346656037ULL;
  for (std::size_t i = kHeaderBytes; i < bytes.size(); ++i) {
    hash ^= static_cast<unsigned char>(bytes[i]);
    hash *= 1099511628211ULL;
  }
  std::memcpy(bytes.data() + 20, &hash, sizeof(hash));
}

std::size_t find(const std::vector<char>& bytes, const std::string& text) {
  const auto it = std::search(bytes.begin(), bytes.end(), text.begin(), text.end());
  return static_cast<std::size_t>(it - bytes.begin());
}

TEST(SvmTest, LearnsASeparableToyProblem) {
  const auto start = std::chrono::steady_clock::now();
  const SvmModel& model = trained();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("trained on %zu descriptors in %.2f s: %zu components, %zu support vectors\n",
              training().size(), seconds, model.components(), model.support_vector_count());
  EXPECT_EQ(model.info.positives + model.info.negatives, training().size());
  EXPECT_EQ(model.info.positives, training().positives());
  EXPECT_GE(model.info.cv_accuracy, 0.95);
  EXPECT_LE(model.components(), 24u);
  const ConfusionMatrix confusion = evaluate(model, held_out(), 2);
  EXPECT_EQ(confusion.total(), held_out().size());
  EXPECT_GE(confusion.accuracy(), 0.97);
  EXPECT_GT(confusion.tp, 0u);
  EXPECT_GT(confusion.tn, 0u);
}

const SvmModel& trained_rbf() {
  static const SvmModel model = [] {
    SvmTrainingOptions o = small_options();
    o.kernels = {SvmKernelType::kRbf};
    return train_svm(training(), o, HandImageOptions{}, HandGeometry{});
  }();
  return model;
}

// Trains OpenCV's SVM (its own solver) with `model`'s kernel on the training set's reduced
// descriptors and checks that the model's decision values on the held-out set are OpenCV's
// (negated): both solve the same problem to the same tolerance, so they agree to a small
// fraction of the values' range and on every label not within that of the boundary.
void expect_opencv_values(const SvmModel& model) {
  const TrainingSet& set = training();
  const std::vector<float> z = model.reduce(set.features.data(), set.size(), set.dimension, 2);
  cv::Mat samples(static_cast<int>(set.size()), static_cast<int>(model.components()), CV_32F,
                  const_cast<float*>(z.data()));
  cv::Mat responses(static_cast<int>(set.size()), 1, CV_32S);
  for (std::size_t i = 0; i < set.size(); ++i)
    responses.at<int>(static_cast<int>(i)) = set.labels[i];
  const cv::Ptr<cv::ml::SVM> svm = cv::ml::SVM::create();
  svm->setType(cv::ml::SVM::C_SVC);
  svm->setKernel(model.kernel.type == SvmKernelType::kRbf ? cv::ml::SVM::RBF : cv::ml::SVM::POLY);
  svm->setDegree(model.kernel.degree);
  svm->setGamma(model.kernel.gamma);
  svm->setCoef0(model.kernel.coef0);
  svm->setC(model.kernel.C);
  svm->setTermCriteria(
      cv::TermCriteria(cv::TermCriteria::MAX_ITER + cv::TermCriteria::EPS, 10000000, 1e-3));
  svm->train(cv::ml::TrainData::create(samples, cv::ml::ROW_SAMPLE, responses));
  const TrainingSet& test = held_out();
  const std::vector<double> ours =
      model.decision_values(test.features.data(), test.size(), test.dimension, 2);
  const std::vector<float> test_z =
      model.reduce(test.features.data(), test.size(), test.dimension, 1);
  const std::vector<double> from_reduced =
      model.decision_values_reduced(test_z.data(), test.size());
  double largest = 0.0;
  double worst = 0.0;
  for (const double v : ours) largest = std::max(largest, std::abs(v));
  const double close = 1e-2 * std::max(1.0, largest);
  for (std::size_t i = 0; i < test.size(); ++i) {
    const cv::Mat row(1, static_cast<int>(model.components()), CV_32F,
                      const_cast<float*>(test_z.data() + i * model.components()));
    const float raw = svm->predict(row, cv::noArray(), cv::ml::StatModel::RAW_OUTPUT);
    // OpenCV's raw value is positive for its first class (-1): ours is its negation.
    EXPECT_NEAR(ours[i], -raw, close) << i;
    worst = std::max(worst, std::abs(ours[i] + raw));
    if (std::abs(ours[i]) > close) {
      EXPECT_EQ(ours[i] > 0.0, svm->predict(row) > 0.0f) << i;
    }
    EXPECT_NEAR(from_reduced[i], ours[i], 1e-9 * std::max(1.0, largest)) << i;
  }
  std::printf("largest difference from OpenCV's values: %.2g (values up to %.2g)\n", worst,
              largest);
}

TEST(SvmTest, DecisionValuesMatchOpenCvsPredict) {
  ASSERT_EQ(trained().kernel.type, SvmKernelType::kPolynomial);
  expect_opencv_values(trained());
}

TEST(SvmTest, GaussianKernelLearnsMatchesOpenCvAndRoundTrips) {
  const SvmModel& model = trained_rbf();
  ASSERT_EQ(model.kernel.type, SvmKernelType::kRbf);
  EXPECT_GE(model.info.cv_accuracy, 0.95);
  EXPECT_GE(evaluate(model, held_out(), 2).accuracy(), 0.97);
  expect_opencv_values(model);
  // f(x) = sum alpha_i exp(-gamma |z - sv_i|^2) - rho, written out for one descriptor.
  const TrainingSet& test = held_out();
  const std::vector<float> z = model.reduce(test.row(0), 1, test.dimension, 1);
  double expected = -model.rho;
  for (std::size_t i = 0; i < model.support_vector_count(); ++i) {
    double distance_squared = 0.0;
    for (std::size_t j = 0; j < model.components(); ++j) {
      const double d = z[j] - model.support_vectors[i * model.components() + j];
      distance_squared += d * d;
    }
    expected += model.alpha[i] * std::exp(-model.kernel.gamma * distance_squared);
  }
  EXPECT_NEAR(model.decision_values(test.row(0), 1, test.dimension, 1)[0], expected, 1e-6);
  const std::string path = temp_path("rbf.model");
  model.save(path);
  const SvmModel loaded = SvmModel::load(path);
  EXPECT_EQ(loaded.kernel.type, SvmKernelType::kRbf);
  EXPECT_EQ(loaded.decision_values(test.features.data(), test.size(), test.dimension, 2),
            model.decision_values(test.features.data(), test.size(), test.dimension, 2));
  const std::vector<char> bytes = bytes_of(path);
  EXPECT_LT(find(bytes, "rbf"), bytes.size());
  fs::remove(path);
}

TEST(SvmTest, CrossValidationChoosesAmongKernels) {
  SvmTrainingOptions o = small_options();
  o.kernels = {SvmKernelType::kPolynomial, SvmKernelType::kRbf};
  const CrossValidationResult cv = cross_validate(training(), o);
  ASSERT_EQ(cv.points.size(), 4u);  // two kernels x two C values, kernel-major
  EXPECT_EQ(cv.points[0].kernel, SvmKernelType::kPolynomial);
  EXPECT_EQ(cv.points[1].kernel, SvmKernelType::kPolynomial);
  EXPECT_EQ(cv.points[2].kernel, SvmKernelType::kRbf);
  EXPECT_EQ(cv.points[3].C, 10.0);
  for (const auto& point : cv.points) {
    EXPECT_LE(point.confusion.accuracy(), cv.accuracy());
  }
  const SvmModel model = train_svm(training(), o);
  EXPECT_EQ(model.kernel.type, cv.best_point().kernel);
  EXPECT_EQ(model.kernel.C, cv.best_point().C);
  EXPECT_EQ(model.info.cv_accuracy, cv.accuracy());
  EXPECT_EQ(kernel_type("rbf"), SvmKernelType::kRbf);
  EXPECT_STREQ(kernel_name(SvmKernelType::kPolynomial), "poly");
  EXPECT_EQ(error_of([] { kernel_type("gauss"); }), "unknown kernel 'gauss' (use poly or rbf)");
  o.kernels.clear();
  EXPECT_NE(error_of([&] { train_svm(training(), o); }).find("no kernel candidates"),
            std::string::npos);
}

TEST(SvmTest, DecisionValuesDoNotDependOnThreadsOrBatching) {
  const TrainingSet& set = held_out();
  for (const SvmModel* kernel_model : {&trained(), &trained_rbf()}) {
    const SvmModel& model = *kernel_model;
    SCOPED_TRACE(kernel_name(model.kernel.type));
    const auto one = model.decision_values(set.features.data(), set.size(), set.dimension, 1);
    const auto two = model.decision_values(set.features.data(), set.size(), set.dimension, 2);
    EXPECT_EQ(one, two);
    // A row alone gives the value it has in a batch (fixed, padded blocks).
    for (const std::size_t i : {std::size_t{0}, std::size_t{130}, set.size() - 1}) {
      const auto alone = model.decision_values(set.row(i), 1, set.dimension, 1);
      EXPECT_EQ(alone[0], one[i]) << i;
    }
    // And the reduced features scored apart give the same values.
    const auto reduced = model.reduce(set.features.data(), set.size(), set.dimension, 2);
    EXPECT_EQ(model.decision_values_reduced(reduced.data(), set.size(), 1), one);
  }
  const SvmModel& model = trained();
  const auto one = model.decision_values(set.features.data(), set.size(), set.dimension, 1);
  std::vector<std::vector<float>> rows;
  for (std::size_t i = 0; i < set.size(); ++i)
    rows.emplace_back(set.row(i), set.row(i) + set.dimension);
  EXPECT_EQ(model.decision_values(rows, 2), one);
  EXPECT_TRUE(model.decision_values(nullptr, 0, set.dimension, 2).empty());
  EXPECT_EQ(error_of([&] { model.decision_values(nullptr, 0, set.dimension, -1); }),
            "SVM model: threads must be >= 0, got -1");
  const std::string wrong = error_of([&] { model.decision_values(set.row(0), 1, 100, 1); });
  EXPECT_NE(wrong.find("descriptors of 100 numbers, but the model takes " +
                       std::to_string(set.dimension)),
            std::string::npos)
      << wrong;
}

TEST(SvmTest, SaveLoadRoundTripKeepsValuesAndBytes) {
  const SvmModel& model = trained();
  const std::string path = temp_path("round_trip.model");
  const std::string again = temp_path("round_trip_again.model");
  model.save(path);
  const SvmModel loaded = SvmModel::load(path);
  loaded.save(again);
  EXPECT_EQ(bytes_of(path), bytes_of(again));
  const TrainingSet& set = held_out();
  EXPECT_EQ(loaded.decision_values(set.features.data(), set.size(), set.dimension, 2),
            model.decision_values(set.features.data(), set.size(), set.dimension, 2));
  EXPECT_EQ(loaded.info.cv_accuracy, model.info.cv_accuracy);
  EXPECT_EQ(loaded.descriptor.name, SvmDescriptorSpec{}.name);
  EXPECT_TRUE(loaded.descriptor.matches(model.descriptor));
  EXPECT_EQ(loaded.kernel.C, model.kernel.C);
  EXPECT_FALSE(loaded.calibration.fitted());
  std::printf("model: %zu components, %zu support vectors, %ju bytes\n", model.components(),
              model.support_vector_count(), static_cast<std::uintmax_t>(fs::file_size(path)));
  SvmModel calibrated = model;
  calibrated.calibration = {-1.25, 0.5, 300};
  calibrated.save(again);
  const SvmModel reloaded = SvmModel::load(again);
  EXPECT_EQ(reloaded.calibration.a, -1.25);
  EXPECT_EQ(reloaded.calibration.b, 0.5);
  EXPECT_EQ(reloaded.calibration.examples, 300u);
  EXPECT_FALSE(reloaded.operating.probability);  // decision values from 0 unless told
  EXPECT_EQ(reloaded.operating.accept, 0.0);
  EXPECT_EQ(reloaded.operating.relaxed, -0.5);
  calibrated.operating = {true, 0.7, 0.4};
  calibrated.save(again);
  const SvmOperatingPoints read = SvmModel::load(again).operating;
  EXPECT_TRUE(read.probability);
  EXPECT_EQ(read.accept, 0.7);
  EXPECT_EQ(read.relaxed, 0.4);
  calibrated.calibration.b = NAN;
  EXPECT_NE(error_of([&] { calibrated.save(again); }).find("non-finite calibration"),
            std::string::npos);
  fs::remove(path);
  fs::remove(again);
}

// A model's operating points must make sense before it is written: finite, relaxed no higher
// than accept, probabilities only of a calibrated model and within [0, 1].
TEST(SvmTest, OperatingPointsAreChecked) {
  SvmModel model = trained();
  const std::string path = temp_path("operating.model");
  const auto save_error = [&](SvmOperatingPoints o) {
    model.operating = o;
    return error_of([&] { model.save(path); });
  };
  EXPECT_NE(save_error({true, 0.7, 0.4}).find("probabilities of an uncalibrated model"),
            std::string::npos);
  model.calibration = {-1.5, 0.1, 100};
  EXPECT_EQ(save_error({true, 0.7, 0.4}), "");
  EXPECT_NE(save_error({true, 0.4, 0.7}).find("relaxed threshold above the accepting one"),
            std::string::npos);
  EXPECT_NE(save_error({true, 1.2, 0.4}).find("outside [0, 1]"), std::string::npos);
  EXPECT_EQ(save_error({false, 1.2, -3.0}), "");  // decision values take any number
  EXPECT_NE(save_error({false, NAN, 0.0}).find("non-finite operating points"), std::string::npos);
  fs::remove(path);
}

// A file of format 5 (before operating points) loads as decision values from 0, -0.5 relaxed.
TEST(SvmTest, FormatFiveModelsLoadWithDecisionOperatingPoints) {
  SvmModel model = trained();
  model.calibration = {-1.5, 0.1, 100};
  model.operating = {true, 0.7, 0.4};
  const std::string path = temp_path("format5.model");
  model.save(path);
  std::vector<char> bytes = bytes_of(path);
  bytes.resize(bytes.size() - 17);  // without the operating points
  const std::uint32_t five = 5;
  const std::uint64_t payload = bytes.size() - kHeaderBytes;
  std::memcpy(bytes.data() + 8, &five, sizeof(five));
  std::memcpy(bytes.data() + 12, &payload, sizeof(payload));
  fix_checksum(bytes);
  write_bytes(path, bytes);
  const SvmModel old = SvmModel::load(path);
  EXPECT_EQ(old.calibration.examples, 100u);
  EXPECT_FALSE(old.operating.probability);
  EXPECT_EQ(old.operating.accept, 0.0);
  EXPECT_EQ(old.operating.relaxed, -0.5);
  fs::remove(path);
}

bool is_half(float v) {
  const float scaled = std::ldexp(std::abs(v), 10 - std::ilogb(v));  // in [1024, 2048)
  return v == 0.0f || std::abs(v) < 6.2e-5f || scaled == std::round(scaled);
}

// Whether `count` numbers `stride` apart from `first` are c * 2^e for one e and integers
// |c| <= 127, the largest |c| being at least 64 (the step is the smallest power of two that
// fits).
bool is_coded(const float* first, std::size_t count, std::size_t stride) {
  float largest = 0.0f;
  for (std::size_t i = 0; i < count; ++i) largest = std::max(largest, std::abs(first[i * stride]));
  float step = std::ldexp(1.0f, -60);
  while (largest > 127.0f * step) step *= 2.0f;
  for (std::size_t i = 0; i < count; ++i) {
    const float c = first[i * stride] / step;
    if (c != std::round(c)) return false;
  }
  return largest >= 64.0f * step;
}

TEST(SvmTest, BasisAndSupportVectorsAreStoredAsTheFileHoldsThem) {
  const SvmModel& model = trained();
  const std::size_t k = model.components();
  ASSERT_EQ(k, 24u);
  const std::size_t h = SvmModel::kHalfPrecisionComponents;
  // Trained numbers are already what the file holds: the basis rows as 8-bit codes, the
  // first h components at half precision (11 significant bits), the others as 8-bit codes...
  const std::size_t d = model.input_dimension();
  for (std::size_t j = 0; j < k; ++j) EXPECT_TRUE(is_coded(&model.basis[j * d], d, 1)) << j;
  std::size_t unrounded = 0;
  for (std::size_t i = 0; i < model.support_vectors.size(); ++i) {
    unrounded += i % k < h && !is_half(model.support_vectors[i]);
  }
  EXPECT_EQ(unrounded, 0u);
  for (std::size_t j = h; j < k; ++j) {
    EXPECT_TRUE(is_coded(&model.support_vectors[j], model.support_vector_count(), k)) << j;
  }
  // ... rounding again changes nothing ...
  SvmModel again = model;
  again.round_support_vectors();
  again.round_basis();
  EXPECT_EQ(again.support_vectors, model.support_vectors);
  EXPECT_EQ(again.basis, model.basis);
  // ... and numbers between those are rounded to the nearest on the way to the file.
  const std::string path = temp_path("rounded.model");
  SvmModel edited = model;
  edited.support_vectors[0] = 1.0f + 1.0f / 4096.0f;  // between two half-precision numbers
  float largest = 0.0f;
  for (std::size_t i = 0; i < model.support_vector_count(); ++i) {
    largest = std::max(largest, std::abs(model.support_vectors[i * k + h]));
  }
  float step = std::ldexp(1.0f, -60);
  while (largest > 127.0f * step) step *= 2.0f;
  const float coded = edited.support_vectors[h];
  ASSERT_LT(std::abs(coded), largest);
  edited.support_vectors[h] = coded + 0.3f * step;  // a third of the way to the next code
  edited.save(path);
  const SvmModel loaded = SvmModel::load(path);
  EXPECT_EQ(loaded.support_vectors[0], 1.0f);
  EXPECT_EQ(loaded.support_vectors[h], coded);
  // Each further support vector costs 2 bytes per half-precision component, 1 per coded one
  // and its coefficient.
  SvmModel twice = edited;
  twice.support_vectors.insert(twice.support_vectors.end(), edited.support_vectors.begin(),
                               edited.support_vectors.end());
  twice.alpha.insert(twice.alpha.end(), edited.alpha.begin(), edited.alpha.end());
  const std::string longer = temp_path("rounded_twice.model");
  twice.save(longer);
  EXPECT_EQ(fs::file_size(longer) - fs::file_size(path),
            edited.support_vector_count() * (2 * h + (k - h) + sizeof(double)));
  edited.support_vectors[0] = 70000.0f;
  EXPECT_EQ(error_of([&] { edited.round_support_vectors(); }),
            "SVM model: support vector number 70000 is beyond half precision's range (65504)");
  EXPECT_NE(error_of([&] { edited.save(path); }).find("beyond half precision's range"),
            std::string::npos);
  edited.support_vectors[0] = 1.0f;
  edited.support_vectors[h] = 70000.0f;  // a coded component takes any size (a coarser step)
  EXPECT_NO_THROW(edited.save(path));
  EXPECT_EQ(SvmModel::load(path).support_vectors[h], 69632.0f);  // 68 x 2^10
  edited.support_vectors[h] = std::numeric_limits<float>::infinity();
  EXPECT_EQ(error_of([&] { edited.round_support_vectors(); }),
            "SVM model: support vector number inf is not finite");
  fs::remove(path);
  fs::remove(longer);
}

TEST(SvmTest, DamagedModelFilesAreClearErrors) {
  const std::string path = temp_path("damaged.model");
  trained().save(path);
  const std::vector<char> good = bytes_of(path);
  auto load_error = [&](std::vector<char> bytes) {
    write_bytes(path, bytes);
    return error_of([&] { SvmModel::load(path); });
  };
  std::vector<char> flipped = good;
  flipped[good.size() / 2] = static_cast<char>(flipped[good.size() / 2] ^ 0x10);
  EXPECT_NE(load_error(flipped).find("corrupted (checksum mismatch)"), std::string::npos);
  const std::vector<char> truncated(good.begin(), good.end() - 100);
  EXPECT_NE(load_error(truncated).find("truncated"), std::string::npos);
  std::vector<char> foreign = good;
  std::memcpy(foreign.data(), "ANTPDATA", 8);
  const std::string foreign_error = load_error(foreign);
  EXPECT_NE(foreign_error.find("not an antipode classifier model file"), std::string::npos)
      << foreign_error;
  EXPECT_NE(foreign_error.find(path), std::string::npos);
  std::vector<char> rbf = good;
  std::memcpy(rbf.data() + find(rbf, "poly"), "rbf_", 4);
  fix_checksum(rbf);
  EXPECT_NE(load_error(rbf).find("unknown kernel 'rbf_'"), std::string::npos);
  std::vector<char> nan = good;
  const double not_a_number = std::nan("");
  // The file ends with rho, positives, negatives, seed, cv accuracy, the (empty) description's
  // length and the calibration's a, b and example count, 8 bytes each, then the operating
  // points: the score kind (1 byte), accept and relaxed (8 bytes each).
  std::memcpy(nan.data() + nan.size() - 89, &not_a_number, sizeof(double));
  fix_checksum(nan);
  EXPECT_NE(load_error(nan).find("non-finite number"), std::string::npos) << load_error(nan);
  // An image size no descriptor needs (a model asking for 200 x 200 px cells would take
  // gigabytes per hand): refused when the file is read.
  // The image options follow the descriptor's name as int32s: cells along, across, cell px.
  std::vector<char> huge = good;
  const HandImageOptions image = trained().descriptor.image;
  std::string options(12, '\0');
  for (int k = 0; k < 3; ++k) {
    const std::int32_t value = k == 0   ? image.cells_along
                               : k == 1 ? image.cells_across
                                        : image.cell_px;
    std::memcpy(options.data() + 4 * k, &value, 4);
  }
  const std::size_t at = find(huge, options);
  ASSERT_LT(at, huge.size());
  const std::int32_t cell_px = 200;
  std::memcpy(huge.data() + at + 8, &cell_px, 4);
  fix_checksum(huge);
  EXPECT_NE(load_error(huge).find("at most 256 x 256 pixels"), std::string::npos)
      << load_error(huge);
  fs::remove(path);
  EXPECT_NE(error_of([&] { SvmModel::load(path); }).find("cannot open classifier model file"),
            std::string::npos);
}

TEST(SvmTest, IncompatibleDescriptorsOrHandsAreRefusedNamingBoth) {
  const SvmModel& model = trained();
  EXPECT_EQ(error_of([&] { model.check_compatible(HandImageOptions{}, HandGeometry{}); }), "");
  HandGeometry deeper;
  deeper.depth_m = 0.08;
  const std::string hand_error =
      error_of([&] { model.check_compatible(HandImageOptions{}, deeper, "model x.svm"); });
  EXPECT_NE(hand_error.find("model x.svm was trained for a 0.06 m deep, 0.072 m wide"),
            std::string::npos)
      << hand_error;
  EXPECT_NE(hand_error.find("this hand set has a 0.08 m deep, 0.072 m wide"), std::string::npos);
  EXPECT_NE(hand_error.find("antipode train --out my.model --set sampler.hand=GRIPPER.yaml"),
            std::string::npos)
      << hand_error;
  HandImageOptions coarse;
  coarse.cell_px = 4;
  const std::string image_error = error_of([&] { model.check_compatible(coarse, HandGeometry{}); });
  EXPECT_NE(image_error.find("HOG cells of 6 px"), std::string::npos) << image_error;
  EXPECT_NE(image_error.find("HOG cells of 4 px"), std::string::npos) << image_error;
  // A file made for another version of the descriptor is refused when it is read.
  SvmModel older = model;
  older.descriptor.name = "occupancy-hog-4";
  const std::string path = temp_path("older_descriptor.model");
  older.save(path);
  const std::string file_error = error_of([&] { SvmModel::load(path); });
  EXPECT_NE(file_error.find(path + ": classifier model file: made for descriptor "
                                   "occupancy-hog-4, but this antipode computes occupancy-hog-5; "
                                   "retrain with `antipode train`"),
            std::string::npos)
      << file_error;
  fs::remove(path);
}

TEST(SvmTest, SameSeedGivesIdenticalModelBytesForAnyThreadCount) {
  SvmTrainingOptions one_thread = small_options();
  one_thread.threads = 1;
  const SvmModel again = train_svm(training(), one_thread, HandImageOptions{}, HandGeometry{});
  const std::string a = temp_path("seed_a.model");
  const std::string b = temp_path("seed_b.model");
  trained().save(a);
  again.save(b);
  EXPECT_EQ(bytes_of(a), bytes_of(b));
  fs::remove(a);
  fs::remove(b);
}

TEST(SvmTest, BadTrainingInputIsAClearError) {
  const HandImageOptions image;
  const HandGeometry hand;
  const SvmTrainingOptions options = small_options();
  EXPECT_NE(error_of([&] { train_svm(TrainingSet{}, options, image, hand); }).find("empty"),
            std::string::npos);
  TrainingSet positives_only;
  RandomStream random(3);
  const auto descriptors = toy_descriptors(std::vector<bool>(6, true), random);
  for (int i = 0; i < 6; ++i)
    positives_only.add(descriptors[static_cast<std::size_t>(i)], true, i, 0);
  EXPECT_NE(error_of([&] {
              train_svm(positives_only, options, image, hand);
            }).find("only positive examples"),
            std::string::npos);
  TrainingSet short_rows;
  short_rows.add({1.0f, 2.0f}, true, 0, 0);
  short_rows.add({2.0f, 1.0f}, false, 1, 0);
  const std::string dimension = error_of([&] { train_svm(short_rows, options, image, hand); });
  EXPECT_NE(dimension.find("descriptors have 2 numbers"), std::string::npos) << dimension;
  EXPECT_NE(dimension.find("gives " + std::to_string(image.descriptor_size())), std::string::npos)
      << dimension;
  SvmTrainingOptions no_c = options;
  no_c.c_values.clear();
  EXPECT_NE(error_of([&] { train_svm(training(), no_c, image, hand); }).find("no C candidates"),
            std::string::npos);
  SvmTrainingOptions no_weight = options;
  no_weight.positive_weight = std::nan("");
  EXPECT_NE(error_of([&] {
              train_svm(training(), no_weight, image, hand);
            }).find("positive_weight must be positive"),
            std::string::npos);
  SvmTrainingOptions too_many_folds = options;
  too_many_folds.folds = 1000;
  EXPECT_NE(error_of([&] {
              cross_validate(training(), too_many_folds);
            }).find("1000 folds need at least 1000 hands, the training set has 80"),
            std::string::npos);
  too_many_folds.folds = 8;
  too_many_folds.folds_by = FoldUnit::kScene;  // the toy set has 7 sources
  EXPECT_NE(error_of([&] {
              cross_validate(training(), too_many_folds);
            }).find("8 folds need at least 8 scenes (distinct sources), the training set has 7"),
            std::string::npos);
  EXPECT_EQ(error_of([] { fold_unit("object"); }),
            "folds by 'object': expected example, hand or scene");
}

TEST(SvmTest, FoldsByExampleHandOrScene) {
  const TrainingSet& set = training();  // hand h: examples 3h..3h+2, source h % 7
  EXPECT_EQ(fold_unit("example"), FoldUnit::kExample);
  EXPECT_EQ(fold_unit("hand"), FoldUnit::kHand);
  EXPECT_EQ(fold_unit("scene"), FoldUnit::kScene);
  const std::vector<int> by_scene = assign_folds(set, 3, 4, FoldUnit::kScene);
  std::vector<int> fold_of_source(7, -1);
  for (std::size_t i = 0; i < set.size(); ++i) {
    int& fold = fold_of_source[static_cast<std::size_t>(set.sources[i])];
    if (fold < 0) fold = by_scene[i];
    EXPECT_EQ(by_scene[i], fold) << i;
  }
  // By example, one hand's three descriptors are dealt one by one: some land apart.
  const std::vector<int> by_example = assign_folds(set, 3, 4, FoldUnit::kExample);
  std::vector<int> per_fold(3, 0);
  bool split = false;
  for (std::size_t i = 0; i < set.size(); ++i) {
    ++per_fold[static_cast<std::size_t>(by_example[i])];
    split = split || by_example[i] != by_example[i - i % 3];
  }
  EXPECT_TRUE(split);
  for (const int n : per_fold) EXPECT_EQ(n, 80);  // 240 examples dealt evenly
}

TEST(SvmTest, ComponentsShareOneScaleAndKeepTheirVarianceOrder) {
  const SvmModel& model = trained();
  ASSERT_GT(model.components(), 2u);
  for (const float scale : model.scale) EXPECT_EQ(scale, model.scale[0]);
  // Reduced training features: variances descend, and average about one (the PCA was fitted
  // on all 240 examples, so exactly one up to float rounding).
  const TrainingSet& set = training();
  const std::vector<float> z = model.reduce(set.features.data(), set.size(), set.dimension, 1);
  const std::size_t k = model.components();
  std::vector<double> variance(k, 0.0);
  for (std::size_t j = 0; j < k; ++j) {
    double sum = 0.0, squares = 0.0;
    for (std::size_t i = 0; i < set.size(); ++i) {
      sum += z[i * k + j];
      squares += static_cast<double>(z[i * k + j]) * z[i * k + j];
    }
    const double n = static_cast<double>(set.size());
    variance[j] = (squares - sum * sum / n) / (n - 1.0);
  }
  double mean = 0.0;
  for (std::size_t j = 0; j < k; ++j) {
    mean += variance[j] / static_cast<double>(k);
    if (j > 0) {
      EXPECT_LE(variance[j], variance[j - 1] * 1.001) << j;
    }
  }
  EXPECT_NEAR(mean, 1.0, 1e-3);
  EXPECT_GT(variance[0], 2.0 * variance[k - 1]);  // not whitened
}

TEST(SvmTest, FoldsKeepGroupsTogetherAndCrossValidationCountsEveryExampleOnce) {
  const TrainingSet& set = training();
  const std::vector<int> folds = assign_folds(set, 4, 9);
  ASSERT_EQ(folds.size(), set.size());
  std::vector<int> per_fold(4, 0);
  for (std::size_t i = 0; i < set.size(); ++i) {
    ASSERT_GE(folds[i], 0);
    ASSERT_LT(folds[i], 4);
    ++per_fold[static_cast<std::size_t>(folds[i])];
    if (i > 0 && set.groups[i] == set.groups[i - 1]) {
      EXPECT_EQ(folds[i], folds[i - 1]);
    }
  }
  for (const int n : per_fold) EXPECT_EQ(n, 60);  // 80 groups of 3, dealt evenly
  EXPECT_EQ(assign_folds(set, 4, 9), folds);
  EXPECT_NE(assign_folds(set, 4, 10), folds);
  SvmTrainingOptions options = small_options();
  options.folds = 4;
  const CrossValidationResult cv = cross_validate(set, options);
  ASSERT_EQ(cv.points.size(), 2u);
  for (const auto& point : cv.points) EXPECT_EQ(point.confusion.total(), set.size());
  EXPECT_GE(cv.accuracy(), 0.95);
  EXPECT_EQ(cv.folds, 4);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Balanced examples from hands sampled on the shared clouds, labelled by the near-antipodal
// check (positive or not); one group per hand.
TrainingSet real_hands(std::size_t wanted) {
  std::vector<Cloud> clouds;
  for (const char* name : {"krylon.pcd", "table_mug.pcd"}) {
    clouds.push_back(load_cloud(std::string(ANTIPODE_TEST_DATA_DIR) + "/clouds/" + name));
  }
  TrainingSet set;
  for (std::uint64_t seed = 0; set.size() < wanted && seed < 10; ++seed) {
    for (const Cloud& cloud : clouds) {
      HandSamplingOptions sampling;
      sampling.search.samples = 1000;
      sampling.search.keep_all_positions = true;
      sampling.search.threads = 2;
      const HandSet hands = sample_hands(cloud, sampling, RandomStream(seed));
      AntipodalLabellingOptions labelling;
      labelling.normals.threads = 2;
      const auto counts = count_antipodal_normals(hands, labelling);
      const auto descriptors = hand_descriptors(hands, hands.geometry, {}, 2);
      for (std::size_t i = 0; i < descriptors.size() && set.size() < wanted; ++i) {
        const bool positive = antipodal_label(counts[i], 6) == HandLabel::kPositive;
        if (positive ? set.positives() > set.negatives() : set.negatives() > set.positives()) {
          continue;
        }
        set.add(descriptors[i], positive, set.next_group(), static_cast<std::int32_t>(seed));
      }
    }
  }
  return set;
}

TEST(SvmTest, TrainsAndPredictsQuicklyOnRealHands) {
  if (!fs::exists(std::string(ANTIPODE_TEST_DATA_DIR) + "/clouds/krylon.pcd")) {
    GTEST_SKIP() << "shared clouds not found; test skipped";
  }
  const auto start_data = std::chrono::steady_clock::now();
  const TrainingSet all = real_hands(6000);
  std::printf("%zu descriptors of real hands in %.1f s\n", all.size(), seconds_since(start_data));
  ASSERT_GE(all.size(), 6000u);
  std::vector<std::size_t> train_rows;
  std::vector<std::size_t> test_rows;
  for (std::size_t i = 0; i < all.size(); ++i) (i % 5 == 4 ? test_rows : train_rows).push_back(i);
  const TrainingSet train = all.subset(train_rows);
  const TrainingSet test = all.subset(test_rows);
  SvmTrainingOptions options;
  options.folds = 3;
  options.c_values = {1.0, 10.0};
  options.threads = 2;
  auto start = std::chrono::steady_clock::now();
  const SvmModel model = train_svm(train, options, HandImageOptions{}, HandGeometry{});
  const double training_s = seconds_since(start);
  std::vector<float> rows;
  while (rows.size() < 4000 * all.dimension) {
    rows.insert(
        rows.end(), all.features.begin(),
        all.features.begin() + static_cast<std::ptrdiff_t>(std::min(
                                   all.features.size(), 4000 * all.dimension - rows.size())));
  }
  start = std::chrono::steady_clock::now();
  const auto values = model.decision_values(rows.data(), 4000, all.dimension, 2);
  const double predict_s = seconds_since(start);
  const ConfusionMatrix confusion = evaluate(model, test, 2);
  std::printf(
      "%zu training descriptors (%zu positive): trained in %.1f s (3 folds x 2 C), C = %g, "
      "%zu components, %zu support vectors, cross-validation %.3f, held-out %.3f; 4000 "
      "decision values in %.1f ms\n",
      train.size(), train.positives(), training_s, model.kernel.C, model.components(),
      model.support_vector_count(), model.info.cv_accuracy, confusion.accuracy(), 1e3 * predict_s);
  EXPECT_EQ(values.size(), 4000u);
  EXPECT_GE(confusion.accuracy(), 0.95);
  EXPECT_LT(predict_s, 2.0);
}

TEST(SvmTest, ConfusionMatrixRates) {
  ConfusionMatrix m{6, 2, 10, 2};
  EXPECT_DOUBLE_EQ(m.accuracy(), 0.8);
  EXPECT_DOUBLE_EQ(m.precision(), 0.75);
  EXPECT_DOUBLE_EQ(m.recall(), 0.75);
  m += ConfusionMatrix{1, 0, 0, 0};
  EXPECT_EQ(m.tp, 7u);
  EXPECT_EQ(ConfusionMatrix{}.accuracy(), 0.0);
  EXPECT_EQ(ConfusionMatrix{}.precision(), 0.0);
}

TEST(TrainingSetTest, SaveLoadRoundTripAndDimensionErrors) {
  const TrainingSet set = toy_set(5, 4);
  const std::string path = temp_path("set.data");
  save_training_set(set, path);
  const TrainingSet loaded = load_training_set(path);
  EXPECT_EQ(loaded.dimension, set.dimension);
  EXPECT_EQ(loaded.features, set.features);
  EXPECT_EQ(loaded.labels, set.labels);
  EXPECT_EQ(loaded.groups, set.groups);
  EXPECT_EQ(loaded.sources, set.sources);
  EXPECT_EQ(loaded.next_group(), 5);
  TrainingSet copy = set;
  const std::string mismatch = error_of([&] { copy.add({1.0f, 2.0f}, true, 9, 0); });
  EXPECT_NE(mismatch.find("descriptor of 2 numbers, but the set holds descriptors of " +
                          std::to_string(set.dimension)),
            std::string::npos)
      << mismatch;
  EXPECT_NE(error_of([&] {
              copy.add(std::vector<float>(set.dimension, NAN), true, 9, 0);
            }).find("non-finite"),
            std::string::npos);
  std::vector<char> bytes = bytes_of(path);
  bytes.resize(bytes.size() - 1);
  write_bytes(path, bytes);
  const std::string truncated = error_of([&] { load_training_set(path); });
  EXPECT_NE(truncated.find("training set file: truncated"), std::string::npos) << truncated;
  EXPECT_NE(truncated.find(path), std::string::npos);
  const std::string model_error = error_of([&] { SvmModel::load(path); });
  EXPECT_NE(model_error.find("not an antipode classifier model file"), std::string::npos)
      << model_error;
  fs::remove(path);
}

// Files of older formats hold descriptors of another layout: refused, saying what to do.
TEST(BinaryFileTest, OlderModelAndTrainingSetFormatsAreRefused) {
  const std::string path = temp_path("old.bin");
  BinaryWriter model("ANTPSVM1", 1);
  model.put_string("occupancy-hog-3");
  model.write(path);
  const std::string model_error = error_of([&] { SvmModel::load(path); });
  EXPECT_NE(model_error.find("format version 1 was written by an older antipode; retrain with "
                             "`antipode train`"),
            std::string::npos)
      << model_error;
  EXPECT_NE(model_error.find(path), std::string::npos) << model_error;
  BinaryWriter single_precision("ANTPSVM1", 2);  // support vectors as floats
  single_precision.put_string("occupancy-hog-4");
  single_precision.write(path);
  EXPECT_NE(error_of([&] { SvmModel::load(path); })
                .find("format version 2 was written by an older antipode; retrain with "
                      "`antipode train`"),
            std::string::npos);
  BinaryWriter examples("ANTPDATA", 3);
  examples.put<std::int32_t>(10);
  examples.write(path);
  const std::string set_error = error_of([&] { load_training_set(path); });
  EXPECT_NE(set_error.find("format version 3 was written by an older antipode; re-create the file"),
            std::string::npos)
      << set_error;
  BinaryWriter without_view_statistics("ANTPDATA", 4);
  without_view_statistics.put<std::int32_t>(10);
  without_view_statistics.write(path);
  EXPECT_NE(error_of([&] {
              load_training_set(path);
            }).find("format version 4 was written by an older antipode; re-create the file"),
            std::string::npos);
  fs::remove(path);
}

TEST(BinaryFileTest, ReaderRefusesFutureVersionsAndOverlongLengths) {
  const std::string path = temp_path("binary.bin");
  BinaryWriter writer("ANTPTEST", 3);
  writer.put<std::uint64_t>(1000);  // a vector length with no elements behind it
  writer.write(path);
  EXPECT_NE(error_of([&] {
              BinaryReader(path, "ANTPTEST", 2, "test");
            }).find("format version 3, but this antipode reads versions 1-2"),
            std::string::npos);
  BinaryReader reader(path, "ANTPTEST", 3, "test");
  EXPECT_NE(error_of([&] { reader.get_vector<double>(); }).find("runs past the end"),
            std::string::npos);
  BinaryReader short_reader(path, "ANTPTEST", 3, "test");
  short_reader.get<std::uint32_t>();
  EXPECT_NE(error_of([&] { short_reader.expect_end(); }).find("4 unexpected bytes at the end"),
            std::string::npos);
  fs::remove(path);
}

}  // namespace
}  // namespace antipode
