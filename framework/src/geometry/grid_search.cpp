// Algorithm 3 (Grid_Search) for one sample, worked in the sample's local frame.
//
// In an orientation phi about the curvature axis, a neighbour q has approach coordinate u
// and closing coordinate v relative to the sample. A hand whose palm face sits at u = t and
// whose centre line sits at v = y holds q at hand coordinates (u - t, v - y). Pushing the
// hand forward (t increasing from spec.start_m) first touches q when
//   t = u - depth  if q lies in a finger's lateral band (the fingertip reaches it),
//   t = u          if q lies elsewhere across the hand (the palm face reaches it),
// and stays in contact until t = u + palm thickness. So one pass over the points per pose
// gives: whether the hand collides where it starts, where it first touches something, and
// the nearest point between the fingers - everything the acceptance test needs.
#include "grid_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace antipode::geometry {
namespace {

// Safety margin of the search over the exact box model: the boxes are inflated by it, so
// float rounding in the local frame never lets a returned hand touch a point.
constexpr float kMargin = 1e-5f;
constexpr float kInfinity = std::numeric_limits<float>::infinity();
// "No contact", and the closing coordinate of padding points.
constexpr float kFar = 1e30f;

// The hand neighbours (already within the hand's half height of the sample's closing plane,
// the only points the hand can touch in any orientation) in local coordinates.
void collect_slab(const Cloud& cloud, const LocalFrame& frame, GridScratch& s) {
  const std::size_t n = s.hand_neighbours.size();
  s.slab_n.resize(n), s.slab_b.resize(n), s.slab_a.resize(n), s.slab_index.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const std::int32_t i = s.hand_neighbours[j];
    const Eigen::Vector3f d = cloud.points_m[static_cast<std::size_t>(i)] - frame.origin_m;
    s.slab_n[j] = d.dot(frame.normal);
    s.slab_b[j] = d.dot(frame.binormal);
    s.slab_a[j] = d.dot(frame.axis);
    s.slab_index[j] = i;
  }
}

// Approach and closing coordinates of the slab points that can touch the hand in the
// orientation (cos_phi, sin_phi): approach = -(c n + s b), closing = s n - c b. Every point is
// written and the write position advances only for the kept ones (no branch to mispredict).
void orient(const GridSpec& spec, float c, float s, GridScratch& g) {
  const std::size_t n = g.slab_index.size();
  g.u.resize(n + 4), g.v.resize(n + 4), g.w.resize(n + 4), g.index.resize(n + 4);
  const float u_min = spec.start_m - spec.palm_thickness_m - kMargin;
  const float u_max = spec.depth_m + kMargin;
  std::size_t kept = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const float u = -(c * g.slab_n[j] + s * g.slab_b[j]);
    const float v = s * g.slab_n[j] - c * g.slab_b[j];
    g.u[kept] = u, g.v[kept] = v, g.w[kept] = g.slab_a[j], g.index[kept] = g.slab_index[j];
    kept += static_cast<std::size_t>((u >= u_min) & (u <= u_max) &
                                     (std::fabs(v) <= spec.max_lateral_m));
  }
  // Padding for the four-wide loop: points far to the side touch nothing.
  for (; kept % 4 != 0; ++kept) {
    g.u[kept] = 0.0f, g.v[kept] = kFar, g.w[kept] = kFar, g.index[kept] = -1;
  }
  g.u.resize(kept), g.v.resize(kept), g.w.resize(kept), g.index.resize(kept);
}

// The nearest contact of the hand body and the nearest point between the fingers along the
// approach, for the hand centred at closing offset `offset`.
struct Contacts {
  float first;    ///< smallest palm position at which the body touches a point
  float between;  ///< smallest approach coordinate of a point between the fingers
};

#if defined(__SSE2__)
// Four points at a time (orient() pads the arrays to a multiple of four with points far to
// the side). Same arithmetic and the same minima as the scalar version below.
Contacts nearest_contacts(const GridSpec& spec, float offset, const GridScratch& g) {
  const __m128 sign = _mm_set1_ps(-0.0f);
  const __m128 centre = _mm_set1_ps(offset);
  const __m128 inner = _mm_set1_ps(spec.half_aperture_m - kMargin);
  const __m128 outer = _mm_set1_ps(spec.half_aperture_m + spec.finger_width_m + kMargin);
  const __m128 body = _mm_set1_ps(spec.body_half_width_m + kMargin);
  const __m128 depth = _mm_set1_ps(spec.depth_m);
  const __m128 margin = _mm_set1_ps(kMargin);
  const __m128 far = _mm_set1_ps(kFar);
  const __m128 start = _mm_set1_ps(spec.start_m);
  __m128 first = far, between = far;
  for (std::size_t j = 0; j < g.u.size(); j += 4) {
    // Most poses collide where they start; once one point says so, the rest cannot change
    // the outcome (checked every 16 points).
    if ((j & 15) == 0 && _mm_movemask_ps(_mm_cmple_ps(first, start)) != 0) break;
    const __m128 u = _mm_loadu_ps(g.u.data() + j);
    const __m128 lateral = _mm_andnot_ps(sign, _mm_sub_ps(_mm_loadu_ps(g.v.data() + j), centre));
    const __m128 in_finger = _mm_and_ps(_mm_cmpge_ps(lateral, inner), _mm_cmple_ps(lateral, outer));
    const __m128 contact = _mm_sub_ps(_mm_sub_ps(u, _mm_and_ps(in_finger, depth)), margin);
    const __m128 in_body = _mm_cmple_ps(lateral, body);
    first = _mm_min_ps(first, _mm_or_ps(_mm_and_ps(in_body, contact), _mm_andnot_ps(in_body, far)));
    const __m128 in_gap = _mm_cmplt_ps(lateral, inner);
    between = _mm_min_ps(between, _mm_or_ps(_mm_and_ps(in_gap, u), _mm_andnot_ps(in_gap, far)));
  }
  alignas(16) float a[4], b[4];
  _mm_store_ps(a, first);
  _mm_store_ps(b, between);
  return {std::min(std::min(a[0], a[1]), std::min(a[2], a[3])),
          std::min(std::min(b[0], b[1]), std::min(b[2], b[3]))};
}
#else
Contacts nearest_contacts(const GridSpec& spec, float offset, const GridScratch& g) {
  const float inner = spec.half_aperture_m - kMargin;
  const float outer = spec.half_aperture_m + spec.finger_width_m + kMargin;
  const float body = spec.body_half_width_m + kMargin;
  Contacts contacts{kFar, kFar};
  for (std::size_t j = 0; j < g.u.size(); ++j) {
    if ((j & 15) == 0 && contacts.first <= spec.start_m) break;  // collides where it starts
    const float lateral = std::fabs(g.v[j] - offset);
    const bool in_finger = lateral >= inner && lateral <= outer;
    const float contact = g.u[j] - (in_finger ? spec.depth_m : 0.0f) - kMargin;
    if (lateral <= body) contacts.first = std::min(contacts.first, contact);
    if (lateral < inner) contacts.between = std::min(contacts.between, g.u[j]);
  }
  return contacts;
}
#endif

// Pushes the hand centred at closing offset `offset` forward from spec.start_m until it
// touches a point, or until its body comes within the support clearance of the support plane
// (palm position `palm_limit`; infinite when pushing forward does not lower the hand), then
// judges it. A hand the support stopped needs only spec.min_bite_at_support_m of bite: the
// object is held down to where the fingers may go.
PoseOutcome evaluate_pose(const GridSpec& spec, float offset, float palm_limit,
                          const GridScratch& g) {
  const Contacts contacts = nearest_contacts(spec, offset, g);
  PoseOutcome pose;
  // orient() dropped every point behind the palm's starting position, so a contact at or
  // before the start means the hand collides there.
  if (contacts.first <= spec.start_m) return pose.rejection = Rejection::kInCollision, pose;
  if (palm_limit < spec.start_m) return pose.rejection = Rejection::kBelowSupport, pose;
  pose.palm_m = std::max(spec.start_m, contacts.first - spec.clearance_m);
  const bool at_support = pose.palm_m > palm_limit;
  if (at_support) pose.palm_m = palm_limit;
  if (!(contacts.between <= pose.palm_m + spec.depth_m)) {
    return pose.rejection = Rejection::kEmptyClosingRegion, pose;
  }
  pose.bite_m = pose.palm_m + spec.depth_m - contacts.between;
  if (pose.bite_m < (at_support ? spec.min_bite_at_support_m : spec.min_bite_m)) {
    return pose.rejection = Rejection::kTooWide, pose;
  }
  pose.acceptable = true;
  return pose;
}

void count(const PoseOutcome& pose, bool hidden, HandSearchStats& stats) {
  ++stats.poses;
  if (pose.acceptable)
    ++stats.acceptable;
  else if (pose.rejection == Rejection::kBelowSupport)
    ++stats.below_support;
  else if (hidden)
    ++stats.hidden;
  else if (pose.rejection == Rejection::kInCollision)
    ++stats.in_collision;
  else if (pose.rejection == Rejection::kEmptyClosingRegion)
    ++stats.empty;
  else
    ++stats.too_shallow;
}

// The positions to turn into hands: every acceptable one, or the middle of the longest run
// of consecutive acceptable ones (the first such run on ties).
void choose_positions(const std::vector<PoseOutcome>& poses, bool keep_all,
                      std::vector<std::size_t>& chosen) {
  chosen.clear();
  std::size_t best_start = 0, best_length = 0;
  for (std::size_t k = 0; k < poses.size();) {
    if (!poses[k].acceptable) {
      ++k;
      continue;
    }
    std::size_t end = k;
    while (end < poses.size() && poses[end].acceptable) {
      if (keep_all) chosen.push_back(end);
      ++end;
    }
    if (end - k > best_length) best_start = k, best_length = end - k;
    k = end;
  }
  if (!keep_all && best_length > 0) chosen.push_back(best_start + (best_length - 1) / 2);
}

// The pose of the hand in the cloud's frame: rotation columns approach, closing, axis; origin
// the centre of the palm face.
Eigen::Isometry3d hand_pose(const LocalFrame& frame, float c, float s, float offset, float palm) {
  const Eigen::Vector3d n = frame.normal.cast<double>(), b = frame.binormal.cast<double>();
  const Eigen::Vector3d approach = -(c * n + s * b);
  const Eigen::Vector3d closing = s * n - c * b;
  Eigen::Matrix3d rotation;
  rotation << approach, closing, frame.axis.cast<double>();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation;
  pose.translation() = frame.origin_m.cast<double>() + palm * approach + offset * closing;
  return pose;
}

// The hand of an accepted pose, with its closing-region points; false if none is left
// (possible only for points on the region's boundary).
bool make_hand(const SampleContext& context, float c, float s, float offset,
               const PoseOutcome& pose, const GridSpec& spec, const GridScratch& g, Hand& hand) {
  hand.closing_points.clear();
  float lo = kInfinity, hi = -kInfinity;
  for (std::size_t j = 0; j < g.u.size(); ++j) {
    const float x = g.u[j] - pose.palm_m;
    const float y = g.v[j] - offset;
    if (x < 0.0f || x > spec.depth_m || std::fabs(y) >= spec.half_aperture_m ||
        std::fabs(g.w[j]) > spec.half_height_m) {
      continue;
    }
    hand.closing_points.push_back(g.index[j]);
    lo = std::min(lo, y), hi = std::max(hi, y);
  }
  if (hand.closing_points.empty()) return false;
  hand.X_FrameHand = hand_pose(context.frame, c, s, offset, pose.palm_m);
  hand.frame = context.cloud.frame;
  hand.width_m = static_cast<double>(hi - lo);
  hand.score = pose.bite_m;
  hand.sample_index = context.sample;
  return true;
}

// The body's extent along the support's normal, relative to the palm face's centre: the
// lowest point of the fingers and palm (three boxes, so the minimum is at a corner).
struct BodyDepth {
  float along_approach, along_closing, along_axis;  // the support normal in hand axes

  float lowest(const GridSpec& spec) const {
    const float z = -std::fabs(along_axis) * spec.half_height_m;
    const float fingers = std::min(0.0f, along_approach * spec.depth_m) -
                          std::fabs(along_closing) * (spec.half_aperture_m + spec.finger_width_m);
    const float palm = std::min(0.0f, -along_approach * spec.palm_thickness_m) -
                       std::fabs(along_closing) * spec.body_half_width_m;
    return std::min(fingers, palm) + z;
  }
};

// The height of the body's lowest point above the support is linear in the palm position:
// h(palm) = h0 + palm * along_approach. The push may go on while h >= the support clearance,
// so it ends at palm = (clearance - h0) / along_approach when the approach points down; when
// it does not, pushing never lowers the hand, and the start decides: -infinity (rejected) if
// the body starts below the clearance, +infinity (no limit) otherwise.
float support_palm_limit(const SampleContext& context, const GridSpec& spec, const BodyDepth& body,
                         float offset) {
  if (context.support == nullptr) return kInfinity;
  const float h0 = context.support->distance(context.frame.origin_m) + offset * body.along_closing +
                   body.lowest(spec);
  if (body.along_approach < -1e-6f) return (spec.support_clearance_m - h0) / body.along_approach;
  const float h_start = h0 + spec.start_m * body.along_approach;
  return h_start >= spec.support_clearance_m ? kInfinity : -kInfinity;
}

// True when a finger of the hand at `pose` reaches into space no sensor saw.
bool finger_hidden(const SampleContext& context, const GridSpec& spec, float c, float s,
                   float offset, const PoseOutcome& pose) {
  const LocalFrame& f = context.frame;
  const Eigen::Vector3f approach = -(c * f.normal + s * f.binormal);
  const Eigen::Vector3f closing = s * f.normal - c * f.binormal;
  const Eigen::Vector3f palm = f.origin_m + pose.palm_m * approach + offset * closing;
  for (const Eigen::Vector3f& probe : spec.finger_probes) {
    const Eigen::Vector3f p =
        palm + probe.x() * approach + probe.y() * closing + probe.z() * f.axis;
    if (context.occlusion->hidden(p, spec.occlusion_margin_m)) return true;
  }
  return false;
}

}  // namespace

GridSpec::GridSpec(const HandSearchParameters& p) {
  const HandGeometry& h = p.hand;
  half_aperture_m = static_cast<float>(h.max_aperture_m / 2.0);
  finger_width_m = static_cast<float>(h.finger_width_m);
  body_half_width_m =
      std::max(static_cast<float>(h.outer_diameter_m / 2.0), half_aperture_m + finger_width_m);
  depth_m = static_cast<float>(h.depth_m);
  half_height_m = static_cast<float>(h.height_m / 2.0);
  palm_thickness_m = static_cast<float>(p.hand.palm_thickness_m);
  start_m = static_cast<float>(-(h.depth_m - h.init_bite_m));
  clearance_m = static_cast<float>(p.clearance_m);
  min_bite_m = static_cast<float>(p.min_bite_m);
  min_bite_at_support_m = static_cast<float>(p.min_bite_at_support_m);
  min_view_cosine = static_cast<float>(std::cos(p.max_view_angle_deg * M_PI / 180.0));
  keep_all_positions = p.keep_all_positions;
  occlusion_margin_m = static_cast<float>(p.occlusion_margin_m);
  support_clearance_m = static_cast<float>(p.support_clearance_m);
  for (const float side : {-1.0f, 1.0f}) {
    for (const float fraction : {1.0f / 3.0f, 2.0f / 3.0f, 1.0f}) {
      finger_probes.emplace_back(fraction * depth_m, side * (half_aperture_m + finger_width_m / 2),
                                 0.0f);
    }
  }
  for (int k = 0; k < p.orientations; ++k) {
    const double phi = -M_PI / 2.0 + M_PI * k / p.orientations;
    cos_phi.push_back(static_cast<float>(std::cos(phi)));
    sin_phi.push_back(static_cast<float>(std::sin(phi)));
    all_orientations.push_back(static_cast<std::size_t>(k));
    if (std::fabs(phi) <= p.tilted_orientation_range_deg * M_PI / 180.0 + 1e-9) {
      tilted_orientations.push_back(static_cast<std::size_t>(k));
    }
  }
  for (const double tilt : p.approach_tilts_deg) {
    tilts_rad.push_back(static_cast<float>(tilt * M_PI / 180.0));
  }
  // Offsets of the hand centre from the sample along closing, centred in the aperture so
  // that the sample is between the fingers in every position.
  const double spacing = h.max_aperture_m / p.positions;
  for (int k = 0; k < p.positions; ++k) {
    offsets_m.push_back(static_cast<float>(-h.max_aperture_m / 2.0 + (k + 0.5) * spacing));
  }
  slab_half_thickness_m = half_height_m + kMargin;
  const float max_offset = std::fabs(offsets_m.front());
  max_lateral_m = max_offset + body_half_width_m + kMargin;
  const float along = std::max(-start_m + palm_thickness_m, depth_m) + kMargin;
  reach_m = std::sqrt(along * along + max_lateral_m * max_lateral_m +
                      (half_height_m + kMargin) * (half_height_m + kMargin));
}

void grid_search(const SampleContext& context, const GridSpec& spec, GridScratch& g,
                 std::vector<Hand>& hands, HandSearchStats& stats) {
  collect_slab(context.cloud, context.frame, g);
  g.poses.resize(spec.offsets_m.size());
  for (const std::size_t k : context.tilted ? spec.tilted_orientations : spec.all_orientations) {
    const float c = spec.cos_phi[k], s = spec.sin_phi[k];
    const Eigen::Vector3f back = c * context.frame.normal + s * context.frame.binormal;
    if (!context.toward_viewer.isZero() && back.dot(context.toward_viewer) < spec.min_view_cosine) {
      ++stats.orientations_unseen;
      continue;
    }
    orient(spec, c, s, g);
    BodyDepth body{0.0f, 0.0f, 0.0f};
    if (context.support != nullptr) {
      const Eigen::Vector3f& up = context.support->normal;
      const LocalFrame& f = context.frame;
      body = {-(c * up.dot(f.normal) + s * up.dot(f.binormal)),
              s * up.dot(f.normal) - c * up.dot(f.binormal), up.dot(f.axis)};
    }
    for (std::size_t p = 0; p < spec.offsets_m.size(); ++p) {
      PoseOutcome& pose = g.poses[p];
      const float offset = spec.offsets_m[p];
      pose = evaluate_pose(spec, offset, support_palm_limit(context, spec, body, offset), g);
      const bool hidden = pose.acceptable && context.occlusion != nullptr &&
                          finger_hidden(context, spec, c, s, offset, pose);
      if (hidden) pose.acceptable = false;
      count(pose, hidden, stats);
    }
    choose_positions(g.poses, spec.keep_all_positions, g.chosen);
    for (const std::size_t p : g.chosen) {
      Hand hand;
      if (make_hand(context, c, s, spec.offsets_m[p], g.poses[p], spec, g, hand)) {
        hands.push_back(std::move(hand));
        ++stats.hands;
        if (context.tilted) ++stats.tilted_hands;
      }
    }
  }
}

}  // namespace antipode::geometry
