#include "hand_clusters.hpp"

#include <cmath>

#include <Eigen/SVD>

namespace antipode::selectors {

bool similar(const Hand& a, const Hand& b, const ClusterOptions& options) {
  const double cos_max = std::cos(options.angle_deg * M_PI / 180.0);
  return a.object == b.object && (a.position_m() - b.position_m()).norm() <= options.distance_m &&
         a.approach().dot(b.approach()) >= cos_max &&
         std::abs(a.closing().dot(b.closing())) >= cos_max;
}

std::vector<std::vector<std::size_t>> cluster_hands(const std::vector<Hand>& hands,
                                                    const std::vector<std::size_t>& order,
                                                    const ClusterOptions& options) {
  std::vector<std::vector<std::size_t>> clusters;
  std::vector<char> taken(order.size(), 0);
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (taken[i]) continue;
    std::vector<std::size_t> members{order[i]};
    taken[i] = 1;
    for (std::size_t j = i + 1; j < order.size(); ++j)
      if (!taken[j] && similar(hands[order[i]], hands[order[j]], options)) {
        members.push_back(order[j]);
        taken[j] = 1;
      }
    clusters.push_back(std::move(members));
  }
  return clusters;
}

Hand mean_hand(const std::vector<Hand>& hands, const std::vector<std::size_t>& members) {
  const Hand& seed = hands[members.front()];
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotations = Eigen::Matrix3d::Zero();
  double score = 0.0, width = 0.0;
  for (const std::size_t m : members) {
    const Hand& hand = hands[m];
    Eigen::Matrix3d r = hand.X_FrameHand.linear();
    if (hand.closing().dot(seed.closing()) < 0.0) {  // half a turn about the approach
      r.col(1) = -r.col(1);
      r.col(2) = -r.col(2);
    }
    rotations += r;
    position += hand.position_m();
    score += hand.score;
    width = std::max(width, hand.width_m);
  }
  // The rotation nearest (in the Frobenius norm) to the sum: U V^T of its SVD.
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(rotations, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d fix = Eigen::Matrix3d::Identity();
  fix(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1.0 : 1.0;
  Hand mean;
  mean.frame = seed.frame;
  mean.X_FrameHand.linear() = svd.matrixU() * fix * svd.matrixV().transpose();
  mean.X_FrameHand.translation() = position / double(members.size());
  mean.width_m = width;
  mean.object = seed.object;
  mean.score = score;
  mean.label = seed.label;
  mean.sample_index = seed.sample_index;
  return mean;
}

}  // namespace antipode::selectors
