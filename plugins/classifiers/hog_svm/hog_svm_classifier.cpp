// The classifier `hog_svm_classifier`: the paper's "SVM" configuration. Each hand's grasp
// hypothesis image is encoded by its HOG descriptor and scored by a trained polynomial-kernel
// SVM; see antipode/grasp/svm_model.hpp and docs/classification.md.
//
// Parameters: model (path, "models/hog_svm.model"), threshold (0), threads (0 = all).
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "antipode/core/error.hpp"
#include "antipode/core/parameters.hpp"
#include "antipode/grasp/hand_image.hpp"
#include "antipode/grasp/svm_model.hpp"
#include "antipode/interfaces/classifier.hpp"
#include "antipode/plugin/abi.hpp"

namespace {
using namespace antipode;
namespace fs = std::filesystem;

SvmModel load_model(const Parameters& params, const std::string& path) {
  try {
    return SvmModel::load(path);
  } catch (const Error& e) {
    params.fail("model", std::string("parameter 'model': ") + e.what() +
                             (fs::exists(path) ? "" : " (train one with `antipode train`)"));
  }
}

class HogSvmClassifier final : public Classifier {
 public:
  explicit HogSvmClassifier(const Parameters& params)
      : path_(
            resolve_path(params.get<std::string>("model", "models/hog_svm.model"), params.file())),
        model_(load_model(params, path_)),
        threshold_(params.get<double>("threshold", 0.0)),
        threads_(params.get<int>("threads", 0)) {
    if (!std::isfinite(threshold_))
      params.fail("threshold", "parameter 'threshold' must be finite");
    if (threads_ < 0 || threads_ > 256) {
      params.fail("threads", "parameter 'threads' must be in 0..256 (0: one per core), got " +
                                 std::to_string(threads_));
    }
    params.reject_unknown();
  }

  void classify(HandSet& set, const StopToken& stop) const override {
    if (set.hands.empty()) return;
    model_.check_compatible(model_.descriptor.image, set.geometry, "model " + path_);
    stop.throw_if_stop_requested("hog_svm_classifier");
    const auto descriptors = hand_descriptors(set, set.geometry, model_.descriptor.image, threads_);
    stop.throw_if_stop_requested("hog_svm_classifier");
    const std::vector<double> values = model_.decision_values(descriptors, threads_);
    stop.throw_if_stop_requested("hog_svm_classifier");
    for (std::size_t i = 0; i < set.hands.size(); ++i) {
      Hand& hand = set.hands[i];
      hand.score = values[i];
      if (values[i] >= threshold_) {
        hand.label = HandLabel::kPositive;
      } else {
        hand.label = HandLabel::kNegative;
        hand.rejection = Rejection::kLowScore;
      }
    }
  }

 private:
  std::string path_;
  SvmModel model_;
  double threshold_;
  int threads_;
};

Component* create_hog_svm(const Parameters& params) { return new HogSvmClassifier(params); }

const PluginFactory kFactories[] = {
    {"classifier", "hog_svm_classifier",
     "labels hands by a trained SVM on HOG descriptors of their grasp images (the paper's SVM)",
     &create_hog_svm, nullptr},
};

}  // namespace

ANTIPODE_PLUGIN("hog_svm_classifier", "1.0.0", kFactories)
