#include "link_bounds.hpp"

#include <algorithm>
#include <numeric>

#include <Eigen/Core>

namespace antipode::collision {

LinkBounds bound_links(const std::vector<int>& owner, const std::vector<int>& link_joint,
                       const std::vector<float>& x, const std::vector<float>& y,
                       const std::vector<float>& z, const std::vector<float>& r, double margin_m) {
  LinkBounds bounds;
  bounds.of_link.assign(link_joint.size(), -1);
  const auto centre_of = [&](std::size_t k) { return Eigen::Vector3d(x[k], y[k], z[k]); };
  for (const bool moving : {true, false})
    for (std::size_t first = 0; first < owner.size();) {
      const int link = owner[first];
      std::size_t end = first + 1;
      while (end < owner.size() && owner[end] == link) ++end;
      if (link >= 0 && (link_joint[std::size_t(link)] >= 0) == moving) {
        Eigen::Vector3d lo = centre_of(first), hi = lo;
        for (std::size_t k = first; k < end; ++k) {
          lo = lo.cwiseMin(centre_of(k));
          hi = hi.cwiseMax(centre_of(k));
        }
        const Eigen::Vector3d centre = (lo + hi) / 2;
        double reach = 0.0;
        for (std::size_t k = first; k < end; ++k)
          reach = std::max(reach, (centre_of(k) - centre).norm() + r[k]);
        bounds.of_link[std::size_t(link)] = int(bounds.link.size());
        bounds.link.push_back(link);
        bounds.joint.push_back(link_joint[std::size_t(link)]);
        bounds.first.push_back(std::int32_t(first));
        bounds.end.push_back(std::int32_t(end));
        bounds.x.push_back(float(centre.x()));
        bounds.y.push_back(float(centre.y()));
        bounds.z.push_back(float(centre.z()));
        bounds.radius.push_back(float(reach + margin_m));
        if (moving) bounds.moving = int(bounds.link.size());
      }
      first = end;
    }
  return bounds;
}

PairGroups group_by_key(std::vector<std::int32_t>& pa, std::vector<std::int32_t>& pb,
                        const std::function<std::pair<int, int>(std::size_t)>& key) {
  std::vector<std::size_t> order(pa.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t p, std::size_t q) { return key(p) < key(q); });
  PairGroups groups;
  std::vector<std::int32_t> sorted_a, sorted_b;
  for (std::size_t n = 0; n < order.size(); ++n) {
    const std::pair<int, int> k = key(order[n]);
    if (n == 0 || k != key(order[n - 1])) {
      groups.a.push_back(k.first);
      groups.b.push_back(k.second);
      groups.first.push_back(std::int32_t(n));
    }
    sorted_a.push_back(pa[order[n]]);
    sorted_b.push_back(pb[order[n]]);
  }
  groups.first.push_back(std::int32_t(order.size()));
  pa = std::move(sorted_a);
  pb = std::move(sorted_b);
  return groups;
}

}  // namespace antipode::collision
