#include "antipode/geometry/point_index.hpp"

#include <nanoflann.hpp>

namespace antipode {
namespace {

// nanoflann's view of the points.
struct PointsAdaptor {
  const std::vector<Eigen::Vector3f>* points;

  std::size_t kdtree_get_point_count() const { return points->size(); }
  float kdtree_get_pt(std::size_t index, std::size_t dim) const {
    return (*points)[index][static_cast<Eigen::Index>(dim)];
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, PointsAdaptor>,
                                                 PointsAdaptor, 3, std::uint32_t>;

// Collects indices (not distances) straight into the caller's vector.
class IndexCollector {
 public:
  IndexCollector(float squared_radius, std::vector<std::int32_t>& out)
      : squared_radius_(squared_radius), out_(out) {}

  void init() {}
  std::size_t size() const { return out_.size(); }
  bool full() const { return true; }
  float worstDist() const { return squared_radius_; }
  bool addPoint(float squared_distance, std::uint32_t index) {
    if (squared_distance <= squared_radius_) out_.push_back(static_cast<std::int32_t>(index));
    return true;
  }

 private:
  float squared_radius_;
  std::vector<std::int32_t>& out_;
};

// Leaves of up to 16 points: measured fastest for 3-10 cm balls at 3 mm point spacing.
constexpr std::size_t kLeafSize = 16;

}  // namespace

struct PointIndex::Impl {
  explicit Impl(const std::vector<Eigen::Vector3f>& points)
      : adaptor{&points}, tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(kLeafSize)) {}

  PointsAdaptor adaptor;
  Tree tree;
};

PointIndex::PointIndex(const std::vector<Eigen::Vector3f>& points)
    : impl_(std::make_unique<Impl>(points)) {}
PointIndex::~PointIndex() = default;
PointIndex::PointIndex(PointIndex&&) noexcept = default;
PointIndex& PointIndex::operator=(PointIndex&&) noexcept = default;

void PointIndex::radius_search(const Eigen::Vector3f& centre, float radius_m,
                               std::vector<std::int32_t>& out) const {
  out.clear();
  if (impl_->adaptor.points->empty()) return;
  IndexCollector collector(radius_m * radius_m, out);
  const float query[3] = {centre.x(), centre.y(), centre.z()};
  impl_->tree.findNeighbors(collector, query, nanoflann::SearchParams(32, 0.0f, false));
}

std::size_t PointIndex::size() const { return impl_->adaptor.points->size(); }

}  // namespace antipode
