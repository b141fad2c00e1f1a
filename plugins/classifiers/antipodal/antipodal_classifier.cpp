// The classifier `antipodal_classifier`: the paper's "A" configuration. Each hand is labelled
// by the near-antipodal check (Definition 3) on the hand set's cloud; see
// antipode/grasp/antipodal.hpp and docs/classification.md.
//
// Parameters: min_points (k, 6), max_angle_deg (theta, 20), contact_depth_m (0.005; 0 =
// the paper's whole closing region), contact_trim (0; 0 = the farthest point is the first
// contact), normal_radius_m (0.01), min_neighbours (10), threads (0 = all).
#include <cmath>
#include <string>

#include "antipode/core/parameters.hpp"
#include "antipode/grasp/antipodal.hpp"
#include "antipode/interfaces/classifier.hpp"
#include "antipode/plugin/abi.hpp"

namespace {
using namespace antipode;

std::string text(double value) {
  std::string s = std::to_string(value);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

double number_in(const Parameters& params, const std::string& key, double fallback, double lower,
                 bool lower_inclusive, double upper) {
  const double value = params.get<double>(key, fallback);
  if (!std::isfinite(value) || value < lower || (!lower_inclusive && value == lower) ||
      value > upper) {
    params.fail(key, "parameter '" + key + "' must be in " + (lower_inclusive ? "[" : "(") +
                         text(lower) + ", " + text(upper) + "], got " + text(value));
  }
  return value;
}

int integer_at_least(const Parameters& params, const std::string& key, int fallback, int lower) {
  const int value = params.get<int>(key, fallback);
  if (value < lower) {
    params.fail(key, "parameter '" + key + "' must be at least " + std::to_string(lower) +
                         ", got " + std::to_string(value));
  }
  return value;
}

AntipodalLabellingOptions read_options(const Parameters& params) {
  AntipodalLabellingOptions o;
  o.antipodal.min_points = integer_at_least(params, "min_points", o.antipodal.min_points, 1);
  o.antipodal.max_angle_deg =
      number_in(params, "max_angle_deg", o.antipodal.max_angle_deg, 0.0, false, 90.0);
  o.antipodal.contact_depth_m =
      number_in(params, "contact_depth_m", o.antipodal.contact_depth_m, 0.0, true, 0.1);
  o.antipodal.contact_trim =
      number_in(params, "contact_trim", o.antipodal.contact_trim, 0.0, true, 0.45);
  o.normals.radius_m = number_in(params, "normal_radius_m", o.normals.radius_m, 0.0, false, 0.1);
  o.normals.min_neighbours = static_cast<std::size_t>(
      integer_at_least(params, "min_neighbours", static_cast<int>(o.normals.min_neighbours), 9));
  o.normals.threads = integer_at_least(params, "threads", o.normals.threads, 0);
  if (o.normals.threads > 256)
    params.fail("threads", "parameter 'threads' must be in 0..256 (0: one per core), got " +
                               std::to_string(o.normals.threads));
  params.reject_unknown();
  return o;
}

class AntipodalClassifier final : public Classifier {
 public:
  explicit AntipodalClassifier(const Parameters& params) : options_(read_options(params)) {}

  void classify(HandSet& set, const StopToken& stop) const override {
    stop.throw_if_stop_requested("antipodal_classifier");
    const std::vector<AntipodalCount> counts = count_antipodal_normals(set, options_);
    stop.throw_if_stop_requested("antipodal_classifier");
    const int k = options_.antipodal.min_points;
    for (std::size_t i = 0; i < set.hands.size(); ++i) {
      Hand& hand = set.hands[i];
      hand.score = antipodal_score(counts[i], k);
      hand.label = antipodal_label(counts[i], k);
      if (hand.label != HandLabel::kPositive) hand.rejection = Rejection::kNotAntipodal;
    }
  }

 private:
  AntipodalLabellingOptions options_;
};

Component* create_antipodal(const Parameters& params) { return new AntipodalClassifier(params); }

void check_antipodal(const Parameters& params) { const AntipodalClassifier checked(params); }

const PluginFactory kFactories[] = {
    {"classifier", "antipodal_classifier",
     "labels hands by the near-antipodal check on the cloud (the paper's Definition 3, A)",
     &create_antipodal, nullptr},
};

const PluginParameterCheck kChecks[] = {{"antipodal_classifier", &check_antipodal}};

}  // namespace

ANTIPODE_PLUGIN_WITH_CHECKS("antipodal_classifier", "1.0.0", kFactories, kChecks)
