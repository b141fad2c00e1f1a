// Training the SVM on real hand descriptors: antipode's solver (svm_solver.hpp), OpenCV's
// cv::ml::SVM and libsvm (when built with it), side by side on the same rows - the first `rows`
// examples of the training set in ANTIPODE_BENCH_TRAINING_SET (a seeded shuffle), reduced by the
// shipped model's PCA. One solve per repetition, single-threaded (as each cross-validation fold
// is). Run with
//   ANTIPODE_BENCH_TRAINING_SET=examples.data svm_solver_bench --benchmark_repetitions=3
// (the 48,000-row cases take minutes each; --benchmark_filter picks cases).
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <numeric>

#include <benchmark/benchmark.h>
#include <opencv2/core.hpp>
#include <opencv2/ml.hpp>

#include "antipode/core/random.hpp"
#include "antipode/grasp/svm_model.hpp"
#include "antipode/grasp/svm_solver.hpp"
#include "antipode/grasp/training_set.hpp"

#ifdef ANTIPODE_BENCH_LIBSVM
#include <libsvm/svm.h>
#endif

namespace antipode {
namespace {

struct Reduced {
  std::vector<float> z;  // rows x components, shuffled
  std::vector<std::int8_t> labels;
  std::size_t k = 0;
};

const char* training_set_path() { return std::getenv("ANTIPODE_BENCH_TRAINING_SET"); }

const Reduced& reduced() {
  static const Reduced data = [] {
    const TrainingSet set = load_training_set(training_set_path());
    const SvmModel model = SvmModel::load(ANTIPODE_BENCH_MODEL);
    const std::vector<float> z = model.reduce(set.features.data(), set.size(), set.dimension, 2);
    std::vector<std::size_t> order(set.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    RandomStream random(7);
    for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[random.below(i)]);
    Reduced r;
    r.k = model.components();
    for (const std::size_t i : order) {
      r.z.insert(r.z.end(), z.begin() + i * r.k, z.begin() + (i + 1) * r.k);
      r.labels.push_back(set.labels[i]);
    }
    return r;
  }();
  return data;
}

bool have_inputs(benchmark::State& state, std::size_t rows) {
  const char* path = training_set_path();
  if (path == nullptr || !std::filesystem::exists(path)) {
    state.SkipWithError("set ANTIPODE_BENCH_TRAINING_SET to a training set file");
    return false;
  }
  if (reduced().labels.size() < rows) {
    state.SkipWithError("the training set has fewer examples than asked for");
    return false;
  }
  return true;
}

// Argument 1: 0 = the polynomial kernel at C 3 (the shipped model's), 1 = the Gaussian kernel
// with gamma 0.04 at C 10.
SvmKernel kernel(std::int64_t which) {
  if (which == 0) return SvmKernel{SvmKernelType::kPolynomial, 3, 1.0 / 96.0, 1.0, 3.0};
  return SvmKernel{SvmKernelType::kRbf, 3, 0.04, 1.0, 10.0};
}

void BM_AntipodeSolver(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  if (!have_inputs(state, rows)) return;
  const Reduced& data = reduced();
  const std::vector<std::int8_t> labels(data.labels.begin(), data.labels.begin() + rows);
  SvmSolverOptions options;
  options.threads = 1;
  options.cache_mib = 2048;
  std::size_t support = 0;
  for (auto _ : state) {
    const SvmDualSolution s =
        solve_svm_dual(data.z.data(), rows, data.k, labels, kernel(state.range(1)), options);
    support = static_cast<std::size_t>(
        std::count_if(s.alpha.begin(), s.alpha.end(), [](double a) { return a > 0.0; }));
    state.counters["iterations"] = static_cast<double>(s.iterations);
  }
  state.counters["support_vectors"] = static_cast<double>(support);
}

void BM_OpenCvSolver(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  if (!have_inputs(state, rows)) return;
  const Reduced& data = reduced();
  const SvmKernel k = kernel(state.range(1));
  cv::Mat samples(static_cast<int>(rows), static_cast<int>(data.k), CV_32F,
                  const_cast<float*>(data.z.data()));
  cv::Mat responses(static_cast<int>(rows), 1, CV_32S);
  for (std::size_t i = 0; i < rows; ++i) responses.at<int>(static_cast<int>(i)) = data.labels[i];
  cv::setNumThreads(1);
  int support = 0;
  for (auto _ : state) {
    const cv::Ptr<cv::ml::SVM> svm = cv::ml::SVM::create();
    svm->setType(cv::ml::SVM::C_SVC);
    svm->setKernel(k.type == SvmKernelType::kRbf ? cv::ml::SVM::RBF : cv::ml::SVM::POLY);
    svm->setDegree(k.degree);
    svm->setGamma(k.gamma);
    svm->setCoef0(k.coef0);
    svm->setC(k.C);
    svm->setTermCriteria(
        cv::TermCriteria(cv::TermCriteria::MAX_ITER + cv::TermCriteria::EPS, 10000000, 1e-3));
    svm->train(cv::ml::TrainData::create(samples, cv::ml::ROW_SAMPLE, responses));
    support = svm->getSupportVectors().rows;
  }
  state.counters["support_vectors"] = support;
}

#ifdef ANTIPODE_BENCH_LIBSVM
// libsvm with a cache as large as antipode's, shrinking on, rows as (index, value) pairs.
void BM_LibsvmSolver(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  if (!have_inputs(state, rows)) return;
  const Reduced& data = reduced();
  const SvmKernel k = kernel(state.range(1));
  std::vector<svm_node> nodes(rows * (data.k + 1));
  std::vector<svm_node*> x(rows);
  std::vector<double> y(rows);
  for (std::size_t i = 0; i < rows; ++i) {
    svm_node* row = nodes.data() + i * (data.k + 1);
    for (std::size_t c = 0; c < data.k; ++c) {
      row[c] = svm_node{static_cast<int>(c + 1), data.z[i * data.k + c]};
    }
    row[data.k] = svm_node{-1, 0.0};
    x[i] = row;
    y[i] = data.labels[i];
  }
  svm_problem problem{static_cast<int>(rows), y.data(), x.data()};
  svm_parameter p{};
  p.svm_type = C_SVC;
  p.kernel_type = k.type == SvmKernelType::kRbf ? RBF : POLY;
  p.degree = k.degree;
  p.gamma = k.gamma;
  p.coef0 = k.coef0;
  p.cache_size = 2048;
  p.eps = 1e-3;
  p.C = k.C;
  p.shrinking = 1;
  svm_set_print_string_function([](const char*) {});
  int support = 0;
  for (auto _ : state) {
    svm_model* model = svm_train(&problem, &p);
    support = model->l;
    svm_free_and_destroy_model(&model);
  }
  state.counters["support_vectors"] = support;
}
#endif

void sizes(benchmark::internal::Benchmark* b) {
  b->ArgNames({"rows", "rbf"});
  for (const std::int64_t kernel : {0, 1}) {
    for (const std::int64_t rows : {5000, 20000, 48000}) b->Args({rows, kernel});
  }
  b->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
}
BENCHMARK(BM_AntipodeSolver)->Apply(sizes);
BENCHMARK(BM_OpenCvSolver)->Apply(sizes);
#ifdef ANTIPODE_BENCH_LIBSVM
BENCHMARK(BM_LibsvmSolver)->Apply(sizes);
#endif

}  // namespace
}  // namespace antipode
