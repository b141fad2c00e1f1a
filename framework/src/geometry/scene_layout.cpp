// The support surface and the objects on it (the contract and the method are in
// scene_layout.hpp): candidate planes by sequential RANSAC, then the objects standing on
// each as Euclidean clusters; the support is the candidate that holds the most.
#include "antipode/geometry/scene_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <numeric>
#include <optional>

#include <Eigen/Geometry>

#include "antipode/core/error.hpp"
#include "antipode/geometry/point_index.hpp"
#include "convex_hull.hpp"
#include "euclidean_clusters.hpp"
#include "plane_facing.hpp"
#include "plane_fit.hpp"

namespace antipode {
namespace {

// Points that score a RANSAC hypothesis: an even stride of at most this many.
constexpr std::size_t kMaxScoringPoints = 4096;
// A support: at most this many points (per inlier) behind it within its extent, and at least
// this fraction of its inliers on a surface seen face-on (plane_facing.hpp).
constexpr double kMaxBelowFraction = 0.1;
constexpr double kMinFacingFraction = 0.6;
// The spacing of a preprocessed cloud's points (its voxel edge).
constexpr float kVoxel_m = 0.003f;

struct Candidate {
  SupportPlane plane;
  std::vector<std::int32_t> inliers;
  Eigen::Vector3f e1, e2;  // in-plane directions
};

using Points = std::vector<Eigen::Vector3f>;

std::vector<std::int32_t> within(const Points& points, const std::vector<std::int32_t>& among,
                                 const SupportPlane& plane, float distance_m) {
  std::vector<std::int32_t> out;
  for (const std::int32_t i : among) {
    if (std::fabs(plane.distance(points[static_cast<std::size_t>(i)])) <= distance_m)
      out.push_back(i);
  }
  return out;
}

// How many of `points` lie within `distance_m` of the plane.
std::size_t count_within(const Points& points, const SupportPlane& plane, float distance_m) {
  std::size_t count = 0;
  for (const Eigen::Vector3f& p : points) count += std::fabs(plane.distance(p)) <= distance_m;
  return count;
}

// The RANSAC plane with the most inliers among an even stride of `among`. The scoring points
// are copied out once: every hypothesis then reads them in order (this loop was a quarter of
// the scene stage's time when it gathered them through their indices for each hypothesis).
std::optional<SupportPlane> ransac_plane(const Points& points,
                                         const std::vector<std::int32_t>& among,
                                         const SceneOptions& o, RandomStream& random) {
  const std::size_t stride = (among.size() + kMaxScoringPoints - 1) / kMaxScoringPoints;
  Points scoring;
  for (std::size_t k = 0; k < among.size(); k += stride)
    scoring.push_back(points[static_cast<std::size_t>(among[k])]);
  std::optional<SupportPlane> best;
  std::size_t best_count = 0;
  for (int iteration = 0; iteration < o.plane_iterations; ++iteration) {
    const auto pick = [&] {
      return points[static_cast<std::size_t>(among[random.below(among.size())])];
    };
    const Eigen::Vector3f a = pick(), b = pick(), c = pick();
    const Eigen::Vector3f cross = (b - a).cross(c - a);
    if (!(cross.norm() > 1e-4f)) continue;
    SupportPlane plane{cross.normalized(), 0.0f, 0};
    plane.offset = -plane.normal.dot(a);
    const std::size_t count = count_within(scoring, plane, o.plane_distance_m);
    if (count > best_count) best = plane, best_count = count;
  }
  return best;
}

// The least-squares plane through the candidate's inliers, with its in-plane directions.
bool refit(const Points& points, Candidate& candidate) {
  Eigen::Matrix<float, 3, 2> spread;
  if (!geometry::refit_plane(points, candidate.inliers, candidate.plane, spread)) return false;
  candidate.e1 = spread.col(0);
  candidate.e2 = candidate.plane.normal.cross(candidate.e1);
  return true;
}

// The next candidate plane among `remaining` (whose inliers it removes from it).
std::optional<Candidate> next_plane(const Points& points, std::vector<std::int32_t>& remaining,
                                    const Eigen::Vector3f& toward_sensor, const SceneOptions& o,
                                    RandomStream& random) {
  if (remaining.size() < std::max<std::size_t>(3, o.min_plane_points)) return std::nullopt;
  const std::optional<SupportPlane> hypothesis = ransac_plane(points, remaining, o, random);
  if (!hypothesis) return std::nullopt;
  Candidate candidate{
      *hypothesis, within(points, remaining, *hypothesis, o.plane_distance_m), {}, {}};
  if (candidate.inliers.size() < o.min_plane_points || !refit(points, candidate))
    return std::nullopt;
  candidate.inliers = within(points, remaining, candidate.plane, o.plane_distance_m);
  if (candidate.inliers.size() < o.min_plane_points) return std::nullopt;
  if (candidate.plane.distance(toward_sensor) < 0.0f) {
    candidate.plane.normal = -candidate.plane.normal,
    candidate.plane.offset = -candidate.plane.offset;
    candidate.e2 = -candidate.e2;
  }
  candidate.plane.inliers = candidate.inliers.size();
  std::vector<std::int32_t> rest;
  std::set_difference(remaining.begin(), remaining.end(), candidate.inliers.begin(),
                      candidate.inliers.end(), std::back_inserter(rest));
  remaining = std::move(rest);
  return candidate;
}

bool inside(const std::vector<Eigen::Vector2f>& hull, const Eigen::Vector2f& q) {
  if (hull.size() < 3) return false;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2f& a = hull[i];
    const Eigen::Vector2f& b = hull[(i + 1) % hull.size()];
    if ((b - a).x() * (q - a).y() - (b - a).y() * (q - a).x() < 0.0f) return false;
  }
  return true;
}

bool in_fixture(const SceneOptions& o, const Eigen::Vector3f& p) {
  return std::any_of(o.fixtures.begin(), o.fixtures.end(),
                     [&](const AxisBox& box) { return box.contains(p); });
}

// The plane's extent: the largest connected patch of its inliers (an even subset of at most
// kMaxPatchPoints, joined by steps of a few times their spacing). A plane through a table
// top also passes through a strip of the wall behind and of every object at that height;
// those strips are not the surface the objects stand on.
constexpr std::size_t kMaxPatchPoints = 8192;

std::vector<std::int32_t> largest_patch(const Points& points,
                                        const std::vector<std::int32_t>& inliers, float voxel_m) {
  const std::size_t stride = (inliers.size() + kMaxPatchPoints - 1) / kMaxPatchPoints;
  std::vector<std::int32_t> subset;
  for (std::size_t k = 0; k < inliers.size(); k += stride) subset.push_back(inliers[k]);
  const float tolerance = std::max(0.02f, 3.0f * std::sqrt(float(stride)) * voxel_m);
  std::vector<std::int32_t> best;
  for (auto& patch : geometry::euclidean_clusters(points, subset, tolerance)) {
    if (patch.size() > best.size()) best = std::move(patch);
  }
  return best;
}

// `p` in the candidate's plane coordinates (along e1 and e2).
Eigen::Vector2f flat(const Candidate& c, const Eigen::Vector3f& p) {
  return Eigen::Vector2f(c.e1.dot(p), c.e2.dot(p));
}

// A cluster of the points above a candidate, measured against the object tests.
struct Segment {
  SceneObject object;
  bool standing = false;  // reaches down to within max_gap_m of the plane
};

// `cluster` measured along the candidate `c`; nullopt when it fails a test other than
// standing (too few points, too flat, cut by the height limit, too wide).
std::optional<Segment> measure(const Points& points, const Candidate& c,
                               std::vector<std::int32_t> cluster, const SceneOptions& o) {
  if (cluster.size() < o.min_object_points) return std::nullopt;
  SceneObject object;
  object.min_m = object.max_m = points[std::size_t(cluster.front())];
  Eigen::Vector2f lo = flat(c, object.min_m), hi = lo;
  float low = o.max_object_height_m;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const std::int32_t i : cluster) {
    const Eigen::Vector3f& p = points[std::size_t(i)];
    object.min_m = object.min_m.cwiseMin(p), object.max_m = object.max_m.cwiseMax(p);
    lo = lo.cwiseMin(flat(c, p)), hi = hi.cwiseMax(flat(c, p));
    low = std::min(low, c.plane.distance(p));
    object.height_m = std::max(object.height_m, c.plane.distance(p));
    sum += p.cast<double>();
  }
  const bool cut = object.height_m > o.max_object_height_m - 0.01f;
  const bool too_flat = object.height_m < o.min_object_height_m;
  if (cut || too_flat || (hi - lo).maxCoeff() > o.max_object_size_m) return std::nullopt;
  object.centroid_m = (sum / static_cast<double>(cluster.size())).cast<float>();
  object.points = std::move(cluster);
  return Segment{std::move(object), low <= o.max_gap_m};
}

// Marks as standing the segments that rest on a standing one: joined to it by a chain of
// segments, each within `max_rest_gap_m` of the next. They are a pile's upper layer, whose
// lower part the layer itself hides from the sensors, so that its lowest visible points are
// far above the plane. The chains are Euclidean clusters of an even subset of the segments'
// points (at most one in kRestStride): the gaps between segments are several voxels wide,
// and every point would cost a radius search of a few hundred neighbours.
constexpr std::size_t kRestStride = 4;

void mark_resting(const Points& points, std::vector<Segment>& segments, const SceneOptions& o) {
  const auto standing = [](const Segment& s) { return s.standing; };
  if (!(o.max_rest_gap_m > 0.0f) || std::all_of(segments.begin(), segments.end(), standing)) return;
  std::vector<std::int32_t> subset;
  std::vector<std::size_t> segment_of(points.size());
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const std::vector<std::int32_t>& members = segments[s].object.points;
    for (std::size_t k = 0; k < members.size(); k += kRestStride) {
      subset.push_back(members[k]);
      segment_of[std::size_t(members[k])] = s;
    }
  }
  std::sort(subset.begin(), subset.end());
  // The segments a pile joins are one group (union-find on segment indices): a segment whose
  // subset falls into several piles joins them all.
  std::vector<std::size_t> group(segments.size());
  std::iota(group.begin(), group.end(), std::size_t{0});
  const auto root = [&group](std::size_t s) {
    while (group[s] != s) s = group[s] = group[group[s]];
    return s;
  };
  for (const auto& pile : geometry::euclidean_clusters(points, subset, o.max_rest_gap_m)) {
    const std::size_t first = root(segment_of[std::size_t(pile.front())]);
    for (const std::int32_t i : pile) group[root(segment_of[std::size_t(i)])] = first;
  }
  std::vector<bool> grounded(segments.size(), false);
  for (std::size_t s = 0; s < segments.size(); ++s)
    if (segments[s].standing) grounded[root(s)] = true;
  for (std::size_t s = 0; s < segments.size(); ++s) segments[s].standing = grounded[root(s)];
}

// The objects on `c`: clusters of the points above it within its extent's footprint that
// stand on it, and those that rest on them. `standing_points` receives how many points the
// standing ones have (what ranks the candidates as supports; resting ones do not count).
std::vector<SceneObject> objects_on(const Points& points, const Candidate& c, const SceneOptions& o,
                                    std::size_t& standing_points) {
  std::vector<Eigen::Vector2f> footprint;
  for (const std::int32_t i : largest_patch(points, c.inliers, kVoxel_m))
    footprint.push_back(flat(c, points[std::size_t(i)]));
  const std::vector<Eigen::Vector2f> hull = geometry::convex_hull(std::move(footprint));
  std::vector<std::int32_t> above;
  std::size_t below = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const float h = c.plane.distance(points[i]);
    if (std::fabs(h) <= o.plane_distance_m || std::fabs(h) > o.max_object_height_m ||
        !inside(hull, flat(c, points[i])))
      continue;
    if (h < 0.0f)
      ++below;
    else if (!in_fixture(o, points[i]))
      above.push_back(static_cast<std::int32_t>(i));
  }
  standing_points = 0;
  std::vector<SceneObject> objects;
  // A support has little behind it within its extent: a plane through an object has the
  // object's far part there.
  if (static_cast<double>(below) > kMaxBelowFraction * static_cast<double>(c.inliers.size()))
    return objects;
  std::vector<Segment> segments;
  for (auto& cluster : geometry::euclidean_clusters(points, above, o.cluster_tolerance_m)) {
    if (std::optional<Segment> segment = measure(points, c, std::move(cluster), o)) {
      if (segment->standing) standing_points += segment->object.points.size();
      segments.push_back(std::move(*segment));
    }
  }
  if (standing_points == 0) return objects;
  mark_resting(points, segments, o);
  for (Segment& segment : segments) {
    if (!segment.standing) continue;
    segment.object.id = static_cast<std::int32_t>(objects.size());
    objects.push_back(std::move(segment.object));
  }
  return objects;
}

}  // namespace

void SceneOptions::validate() const {
  const auto require = [](bool ok, const std::string& what) {
    if (!ok) throw Error("scene: " + what);
  };
  require(max_planes >= 1 && max_planes <= 20, "max_planes must be in 1..20");
  require(min_plane_points >= 3, "min_plane_points must be at least 3");
  require(plane_distance_m > 0.0f && plane_distance_m < 0.1f,
          "plane_distance_m must be in (0, 0.1)");
  require(plane_iterations >= 1 && plane_iterations <= 100000,
          "plane_iterations must be in 1..100000");
  require(max_object_height_m > plane_distance_m + 0.01f && max_object_height_m <= 5.0f,
          "max_object_height_m must be above plane_distance_m + 0.01 and at most 5");
  require(max_object_size_m > 0.0f && max_object_size_m <= 10.0f,
          "max_object_size_m must be in (0, 10]");
  require(min_object_height_m >= plane_distance_m && min_object_height_m < max_object_height_m,
          "min_object_height_m must be in [plane_distance_m, max_object_height_m)");
  require(max_gap_m >= 0.0f && max_gap_m < max_object_height_m,
          "max_gap_m must be in [0, max_object_height_m)");
  require(max_rest_gap_m >= 0.0f && max_rest_gap_m < 0.1f, "max_rest_gap_m must be in [0, 0.1)");
  require(cluster_tolerance_m > 0.0f && cluster_tolerance_m < 0.1f,
          "cluster_tolerance_m must be in (0, 0.1)");
  require(min_object_points >= 1, "min_object_points must be at least 1");
  require(!up || (up->allFinite() && std::fabs(up->norm() - 1.0f) < 1e-3f),
          "up must be a unit vector");
  require(max_tilt_deg >= 0.0f && max_tilt_deg <= 90.0f, "max_tilt_deg must be in [0, 90]");
  for (const AxisBox& box : fixtures) box.validate("scene fixture");
}

SceneLayout find_scene_layout(const Cloud& cloud, const Eigen::Vector3f& toward_sensor,
                              const SceneOptions& options, RandomStream random) {
  options.validate();
  SceneLayout layout;
  layout.object_of_point.assign(cloud.size(), -1);
  std::vector<std::int32_t> remaining(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) remaining[i] = static_cast<std::int32_t>(i);
  const float min_cosine = std::cos(options.max_tilt_deg * float(M_PI) / 180.0f);
  const PointIndex index(cloud.points_m);
  std::size_t best_points = 0, best_inliers = 0;
  for (int k = 0; k < options.max_planes; ++k) {
    const std::optional<Candidate> c =
        next_plane(cloud.points_m, remaining, toward_sensor, options, random);
    if (!c) break;
    ++layout.planes;
    if (options.up && c->plane.normal.dot(*options.up) < min_cosine) continue;
    if (geometry::facing_fraction(cloud.points_m, index, c->inliers, c->plane) < kMinFacingFraction)
      continue;
    std::size_t n = 0;
    std::vector<SceneObject> objects = objects_on(cloud.points_m, *c, options, n);
    if (n == 0 || n < best_points || (n == best_points && c->inliers.size() <= best_inliers))
      continue;
    best_points = n, best_inliers = c->inliers.size();
    layout.support = c->plane;
    layout.objects = std::move(objects);
  }
  for (const SceneObject& object : layout.objects) {
    for (const std::int32_t i : object.points) layout.object_of_point[std::size_t(i)] = object.id;
  }
  return layout;
}

}  // namespace antipode
