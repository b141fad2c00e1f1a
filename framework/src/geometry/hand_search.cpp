// Algorithm 2 (Sample_Hands) over a preprocessed cloud, parallel over samples.
#include "antipode/geometry/hand_search.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "antipode/core/error.hpp"
#include "antipode/geometry/occlusion.hpp"
#include "antipode/geometry/point_index.hpp"
#include "cloud_select.hpp"
#include "grid_search.hpp"
#include "sample_choice.hpp"
#include "slab_grid.hpp"

namespace antipode {
namespace {

// Stream index of the sample choice; per-sample work uses random.derive(1 + sample), and
// the support plane a stream no sample index reaches.
constexpr std::uint64_t kSampleChoiceStream = 0;
constexpr std::uint64_t kSupportPlaneStream = 0xFFFFFFFFFFFFull;

struct SampleOutput {
  std::vector<Hand> hands;
  HandSearchStats stats;
};

// Steps 4-8 of Algorithm 2 for one sampled point.
struct SearchContext {
  const Cloud& cloud;
  const PointIndex& index;
  const geometry::SlabGrid& slabs;
  const HandSearchParameters& parameters;
  const geometry::GridSpec& spec;
  const OcclusionMap* occlusion;
  const SupportPlane* support;
};

// Samples whose curvature axis is within this angle of level get no tilted frames: turning
// their frame about the binormal would swing the approach sideways rather than down.
const float kMinTiltAxisSine = std::sin(15.0f * static_cast<float>(M_PI) / 180.0f);

// The frame `f` turned about its binormal by `tilt_rad`, in the direction that lowers the
// approach at phi = 0 (-normal) relative to `up`; nullopt when its axis is about level.
// With (normal, binormal, axis) right-handed, a turn by t about the binormal gives
// normal' = cos t normal - sin t axis and axis' = sin t normal + cos t axis, so the approach
// -normal' gains sin t (axis . up) along up: t takes the sign opposite to axis . up.
std::optional<LocalFrame> tilted_frame(const LocalFrame& f, const Eigen::Vector3f& up,
                                       float tilt_rad) {
  const float axis_up = f.axis.dot(up);
  if (std::fabs(axis_up) < kMinTiltAxisSine) return std::nullopt;
  const float t = axis_up > 0.0f ? -tilt_rad : tilt_rad;
  LocalFrame turned = f;
  turned.normal = (std::cos(t) * f.normal - std::sin(t) * f.axis).normalized();
  turned.axis = (std::sin(t) * f.normal + std::cos(t) * f.axis).normalized();
  return turned;
}

void search_sample(const SearchContext& search, std::int32_t sample, geometry::GridScratch& scratch,
                   SampleOutput& out) {
  const Cloud& cloud = search.cloud;
  const HandSearchParameters& p = search.parameters;
  out.stats.samples = 1;
  const Eigen::Vector3f& point = cloud.points_m[static_cast<std::size_t>(sample)];
  search.index.radius_search(point, static_cast<float>(p.frame_radius_m), scratch.frame_neighbours);
  const Eigen::Vector3f viewer =
      geometry::toward_viewer(cloud, static_cast<std::size_t>(sample), p.outward_from_m);
  const LocalFrame frame =
      estimate_local_frame(cloud.points_m, scratch.frame_neighbours, point, viewer, p.frame);
  switch (frame.status) {
    case FrameStatus::kTooFewPoints:
      ++out.stats.skipped_too_few;
      return;
    case FrameStatus::kCollinear:
      ++out.stats.skipped_collinear;
      return;
    case FrameStatus::kQuadric:
      ++out.stats.frames_quadric;
      break;
    case FrameStatus::kPlanar:
      ++out.stats.frames_planar;
      break;
  }
  search.slabs.query(point, frame.axis, search.spec.slab_half_thickness_m, search.spec.reach_m,
                     scratch.hand_neighbours);
  const geometry::SampleContext context{cloud,         frame, sample, viewer, search.occlusion,
                                        search.support};
  geometry::grid_search(context, search.spec, scratch, out.hands, out.stats);
  if (search.support == nullptr) return;
  for (const float tilt_rad : search.spec.tilts_rad) {
    const std::optional<LocalFrame> turned = tilted_frame(frame, search.support->normal, tilt_rad);
    if (!turned) break;
    search.slabs.query(point, turned->axis, search.spec.slab_half_thickness_m, search.spec.reach_m,
                       scratch.hand_neighbours);
    geometry::SampleContext tilted{cloud,  *turned,          sample,
                                   viewer, search.occlusion, search.support};
    tilted.tilted = true;
    geometry::grid_search(tilted, search.spec, scratch, out.hands, out.stats);
  }
}

// Indices of the points samples may be drawn from: those in the region (if set) and not on
// or below the support (if any); `on_support` counts the points the support excluded.
std::vector<std::int32_t> candidates(const Cloud& cloud, const std::optional<AxisBox>& region,
                                     const SupportPlane* support, float support_distance_m,
                                     const SearchScene& scene, std::size_t& on_support) {
  std::vector<char> allowed(cloud.size(), scene.sample_points ? 0 : 1);
  if (scene.sample_points) {
    for (const std::int32_t i : *scene.sample_points) {
      if (i >= 0 && static_cast<std::size_t>(i) < cloud.size()) allowed[std::size_t(i)] = 1;
    }
  }
  std::vector<std::int32_t> indices;
  indices.reserve(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!allowed[i]) continue;
    const Eigen::Vector3f& p = cloud.points_m[i];
    if (region && !region->contains(p)) continue;
    if (support != nullptr && support->distance(p) <= support_distance_m) {
      ++on_support;
      continue;
    }
    indices.push_back(static_cast<std::int32_t>(i));
  }
  return indices;
}

HandSearchResult concatenate(std::vector<SampleOutput>& outputs, std::vector<std::int32_t> samples,
                             HandSearchResult result) {
  result.sample_points = std::move(samples);
  std::size_t total = 0;
  for (const auto& out : outputs) total += out.hands.size();
  result.hands.reserve(total);
  for (auto& out : outputs) {
    std::move(out.hands.begin(), out.hands.end(), std::back_inserter(result.hands));
    result.stats += out.stats;
  }
  return result;
}

}  // namespace

HandSearchResult search_hands(const Cloud& cloud, const HandSearchParameters& parameters,
                              const RandomStream& random, const SearchScene& scene) {
  parameters.validate();
  if (cloud.empty()) throw Error("hand search: the cloud has no points");
  cloud.validate();
  const geometry::GridSpec spec(parameters);
  const PointIndex index(cloud.points_m);
  std::unique_ptr<OcclusionMap> occlusion;
  if (parameters.reject_hidden_fingers) {
    occlusion =
        std::make_unique<OcclusionMap>(cloud, static_cast<float>(parameters.point_radius_m));
  }
  HandSearchResult result;
  const bool all_around = cloud.view_origins_m.empty() && parameters.outward_from_m;
  if (scene.support) {
    result.support_plane = scene.support;
  } else if (parameters.support_plane == SupportPlaneMode::kAuto && !all_around) {
    result.support_plane =
        find_support_plane(cloud, geometry::sensor_position(cloud), parameters.support,
                           random.derive(kSupportPlaneStream));
  }
  const SupportPlane* support = result.support_plane ? &*result.support_plane : nullptr;
  const geometry::SlabGrid slabs(cloud.points_m, geometry::kSlabCell_m);
  const SearchContext search{cloud, index, slabs, parameters, spec, occlusion.get(), support};
  std::vector<std::int32_t> samples = geometry::choose_samples(
      candidates(cloud, parameters.sample_region, support, parameters.support.distance_m, scene,
                 result.stats.on_support),
      parameters.samples, random.derive(kSampleChoiceStream));
  std::vector<SampleOutput> outputs(samples.size());
  tbb::enumerable_thread_specific<geometry::GridScratch> scratch;
  tbb::task_arena arena(parameters.threads > 0 ? parameters.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples.size(), 8),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        geometry::GridScratch& local = scratch.local();
                        for (std::size_t i = range.begin(); i != range.end(); ++i) {
                          search_sample(search, samples[i], local, outputs[i]);
                        }
                      });
  });
  return concatenate(outputs, std::move(samples), std::move(result));
}

}  // namespace antipode
