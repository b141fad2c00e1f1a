#include "table_top_selector.hpp"

#include <algorithm>

namespace antipode::cells {
namespace {

double in_range(const Parameters& p, const std::string& key, double fallback, double lo,
                double hi) {
  const double value = p.get<double>(key, fallback);
  if (!(value >= lo && value <= hi))
    p.fail(key,
           "'" + key + "' must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return value;
}

}  // namespace

TableTopSelector::TableTopSelector(const Parameters& params) {
  table_z_m_ = params.require<double>("table_z_m");
  standoff_m_ = in_range(params, "standoff_m", standoff_m_, 0.0, 0.5);
  clearance_m_ = in_range(params, "clearance_m", clearance_m_, 0.0, 0.1);
  palm_thickness_m_ = in_range(params, "palm_thickness_m", palm_thickness_m_, 0.0, 0.2);
  max_grasps_ = std::size_t(in_range(params, "max_grasps", double(max_grasps_), 1, 1e6));
  params.reject_unknown();
}

bool TableTopSelector::clears_table(const Hand& hand) const {
  const HandGeometry& g = geometry_;
  const double half_width =
      std::max(g.outer_diameter_m, g.max_aperture_m + 2 * g.finger_width_m) / 2;
  for (double back : {0.0, standoff_m_})
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d p(((corner & 1) ? g.depth_m : -palm_thickness_m_) - back,
                              (corner & 2) ? half_width : -half_width,
                              ((corner & 4) ? 0.5 : -0.5) * g.height_m);
      if ((hand.X_FrameHand * p).z() < table_z_m_ + clearance_m_) return false;
    }
  return true;
}

std::vector<Hand> TableTopSelector::select(const HandSet& hands) const {
  std::vector<Hand> kept;
  for (const Hand& hand : hands.hands)
    if (hand.rejection == Rejection::kNone && clears_table(hand)) kept.push_back(hand);
  std::stable_sort(kept.begin(), kept.end(),
                   [](const Hand& a, const Hand& b) { return a.score > b.score; });
  if (kept.size() > max_grasps_) kept.resize(max_grasps_);
  return kept;
}

}  // namespace antipode::cells
