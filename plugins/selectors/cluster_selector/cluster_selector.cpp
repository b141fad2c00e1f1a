#include "cluster_selector.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <tuple>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "antipode/core/error.hpp"
#include "antipode/geometry/hand_body.hpp"
#include "closing_tilt.hpp"
#include "contact_depth.hpp"
#include "finger_cover.hpp"
#include "grasp_balance.hpp"
#include "hand_clearance.hpp"
#include "hand_clusters.hpp"
#include "held_width.hpp"

namespace antipode::selectors {
namespace {

// A grasp a cluster proposes, with the input hands it stands for.
struct Proposal {
  Hand grasp;
  std::vector<std::size_t> members;
  double tilt = 0.0;     // the closing direction's tilt from the support
  double penalty = 0.0;  // criterion 2: the aperture
  double balance = 0.0;  // gravity's lever about the closing axis
  double arm_m = 0.0;
  double mean_score = 0.0;  // the members' mean score
};

// The median of values[m] over the members m (the upper one of an even count).
double median_of(const std::vector<double>& values, const std::vector<std::size_t>& members) {
  std::vector<double> picked;
  picked.reserve(members.size());
  for (const std::size_t m : members) picked.push_back(values[m]);
  const auto middle = picked.begin() + static_cast<std::ptrdiff_t>(picked.size() / 2);
  std::nth_element(picked.begin(), middle, picked.end());
  return *middle;
}

constexpr std::int32_t kAnyObject = -2;

// The depth of a finger's contact patch along the closing direction (contact_depth.hpp): the
// points a finger meets within the first 3 mm of its closing.
constexpr double kContactPatchM = 0.003;

// The object the selection is asked for: `object`, the one nearest `near_m` (-1, none,
// when the set has no objects), or kAnyObject.
std::int32_t object_of_interest(const HandSet& set, const SelectionOptions& o) {
  if (o.object >= 0) return o.object;
  if (!o.near_m) return kAnyObject;
  std::int32_t nearest = -1;
  double best = std::numeric_limits<double>::infinity();
  for (const SceneObject& object : set.objects) {
    const double d = (object.centroid_m.cast<double>() - *o.near_m).norm();
    if (d < best) best = d, nearest = object.id;
  }
  return nearest;
}

double beyond(double value, double free) {
  return value <= free ? 0.0 : (value - free) * (value - free);
}

// What every hand is measured against, built once per selection.
struct Fixtures {
  std::optional<SupportPlane> support;  // the hand set's, else one at `support_z_m`
  HandBody body;
  std::optional<BinWalls> bin_walls;
  std::vector<Eigen::Vector3f> objects;  // the points more than 1 cm above the support
  Eigen::Vector3d up;                    // the support's normal (+z without one)
};

// Where the mass of what a grasp holds lies, as the views show it: the centroid of the
// object points within object_radius_m of the grasp, of its own object's points only when
// the scene was segmented (the hand names its object) - in clutter, the neighbours' points
// would pull it into the pile.
std::optional<Eigen::Vector3d> mass_centre(const HandSet& in, const Fixtures& f, const Hand& grasp,
                                           const SelectionOptions& o) {
  const Eigen::Vector3d centre = grasp_centre(grasp, in.geometry);
  if (grasp.object >= 0)
    for (const SceneObject& object : in.objects)
      if (object.id == grasp.object)
        return object_centroid_near(*in.cloud, object, centre, o.object_radius_m);
  return centroid_near(f.objects, centre, o.object_radius_m);
}

Fixtures fixtures_of(const HandSet& in, const SelectionOptions& o) {
  Fixtures f{in.support, make_hand_body(in.geometry), std::nullopt, {}, Eigen::Vector3d::UnitZ()};
  if (!f.support && o.support_z_m)
    f.support = SupportPlane{Eigen::Vector3f::UnitZ(), float(-*o.support_z_m), 0};
  if (o.bin) f.bin_walls.emplace(*o.bin, f.body);
  f.objects = object_points(*in.cloud, f.support, 0.01f);
  if (f.support) f.up = f.support->normal.cast<double>();
  return f;
}

// The support, the bin's walls and the open gripper: what rejects a hand before its held
// width (the costly part, held_width.hpp) is needed.
Rejection misplaced(const Hand& hand, const HandGeometry& g, const Fixtures& f,
                    const SelectionOptions& o) {
  if (f.support && !clears_support(hand, g, *f.support, o.standoff_m, o.clearance_m))
    return Rejection::kBelowSupport;
  if (f.bin_walls && f.bin_walls->reached_by(hand)) return Rejection::kInCollision;
  if (hand.width_m > g.max_aperture_m) return Rejection::kApertureLimit;
  return Rejection::kNone;
}

// Whether `check_each` also drops the hands widest beyond the fingertips. Before classification
// it must not: select() tries them after all when nothing else is left, and then needs them
// classified.
enum class TipsCheck { kApply, kLeaveForSelection };

// The checks of one hand on its own (docs/selection.md, steps 1-3): its rejection, and its held
// width when it was measured (else 0). `scratch` is working space.
std::pair<Rejection, double> check_one(const Hand& hand, const HandSet& in, const Fixtures& f,
                                       const SelectionOptions& o, TipsCheck tips,
                                       std::vector<float>& scratch) {
  const HandGeometry& g = in.geometry;
  if (const Rejection why = misplaced(hand, g, f, o); why != Rejection::kNone) return {why, 0.0};
  const double held = held_width_m(hand, *in.cloud, o.width_trim, o.squeeze_turn_deg, scratch);
  if (held < g.min_aperture_m) return {Rejection::kApertureLimit, held};
  if (finger_cover(hand, *in.cloud, g, o.width_trim, scratch) < o.min_finger_cover)
    return {Rejection::kFingersOverAnEdge, held};
  if (tips == TipsCheck::kApply && o.fingertip_margin_m > 0.0 &&
      contact_start_m(hand, *in.cloud, kContactPatchM) > g.depth_m - o.fingertip_margin_m)
    return {Rejection::kWidestBeyondTheTips, held};
  return {Rejection::kNone, held};
}

// check_one for every selectable hand of `hands` (the input's), `o.threads` at a time (each
// hand on its own: the same result for any number): sets their rejections and returns their
// held widths (0 for hands not measured).
std::vector<double> check_each(std::vector<Hand>& hands, const HandSet& in, const Fixtures& f,
                               const SelectionOptions& o, TipsCheck tips = TipsCheck::kApply) {
  std::vector<double> held(hands.size(), 0.0);
  tbb::task_arena arena(o.threads > 0 ? o.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, hands.size(), 32),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        std::vector<float> scratch;
                        for (std::size_t i = range.begin(); i < range.end(); ++i) {
                          if (!selectable(hands[i])) continue;
                          std::tie(hands[i].rejection, held[i]) =
                              check_one(hands[i], in, f, o, tips, scratch);
                        }
                      });
  });
  return held;
}

}  // namespace

double aperture_penalty(double held_width_m, double width_m, const HandGeometry& geometry,
                        double margin_m) {
  const double distance =
      std::min(held_width_m - geometry.min_aperture_m, geometry.max_aperture_m - width_m);
  return distance >= margin_m ? 0.0 : (margin_m - distance) * (margin_m - distance);
}

ClusterSelector::ClusterSelector(const SelectionOptions& options) : options_(options) {
  if (!options_.arm.robot_file.empty()) arm_ = std::make_shared<const ArmReach>(options_.arm);
}

ClusterSelector::ClusterSelector(const Parameters& params)
    : options_(read_selection_options(params)) {
  if (options_.arm.robot_file.empty()) return;
  try {
    arm_ = std::make_shared<const ArmReach>(options_.arm);
  } catch (const Error& e) {
    params.fail("robot", std::string("parameter 'robot': ") + e.what());
  }
}

namespace {

// Clusters the hands `check_each` kept, ranks the clusters' grasps and keeps the first that are
// free to reach (docs/selection.md, steps 4-8); the selection's result, as select() returns.
HandSet choose(std::vector<Hand> hands, const std::vector<double>& held, const HandSet& in,
               const Fixtures& f, const SelectionOptions& o, const ArmReach* arm,
               const SelectionContext& context) {
  const HandGeometry& g = in.geometry;
  const auto feasible = [&](const Hand& hand, double held_width_m) {
    const Rejection why = misplaced(hand, g, f, o);
    if (why != Rejection::kNone) return why;
    return held_width_m < g.min_aperture_m ? Rejection::kApertureLimit : Rejection::kNone;
  };
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < hands.size(); ++i)
    if (selectable(hands[i]) && hands[i].rejection == Rejection::kNone) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return hands[a].score > hands[b].score; });

  std::vector<Proposal> proposals;
  for (auto& members : cluster_hands(hands, order, {o.cluster_distance_m, o.cluster_angle_deg})) {
    if (members.size() < o.min_cluster_size) {
      for (std::size_t m : members) hands[m].rejection = Rejection::kSmallCluster;
      continue;
    }
    Proposal p;
    p.grasp = mean_hand(hands, members);
    const double held_width = median_of(held, members);
    if (feasible(p.grasp, held_width) != Rejection::kNone ||
        !approach_is_free(p.grasp, g, *in.cloud, o.standoff_m))
      p.grasp.X_FrameHand = hands[members.front()].X_FrameHand;  // the seed passed them
    p.members = std::move(members);
    p.mean_score = p.grasp.score / double(p.members.size());
    p.tilt = tilt_penalty(closing_tilt_rad(p.grasp, f.up), o.tilt_free_deg * M_PI / 180.0);
    p.penalty = aperture_penalty(held_width, p.grasp.width_m, g, o.aperture_margin_m);
    if (const auto centroid = mass_centre(in, f, p.grasp, o)) {
      p.arm_m = torque_arm_m(p.grasp, g, *centroid, f.up);
      p.balance = beyond(p.arm_m, o.balance_free_m);
    }
    proposals.push_back(std::move(p));
  }
  std::stable_sort(proposals.begin(), proposals.end(), [&](const Proposal& a, const Proposal& b) {
    const double first = in.scores == ScoreMeaning::kProbability ? o.score_first_tolerance : 0.0;
    if (first > 0.0 && std::abs(a.mean_score - b.mean_score) > first)
      return a.mean_score > b.mean_score;
    if (std::abs(a.tilt - b.tilt) > o.tilt_tolerance_rad2) return a.tilt < b.tilt;
    const double tolerance = o.penalty_tolerance_m2;
    if (std::abs(a.penalty - b.penalty) > tolerance) return a.penalty < b.penalty;
    if (std::abs(a.balance - b.balance) > tolerance) return a.balance < b.balance;
    return a.grasp.score > b.grasp.score;
  });

  // Grasps whose lever arm is beyond the limit come last, and are tried only when no other
  // grasp remains: an attempt that may turn out of the fingers beats no attempt.
  const auto unbalanced = [&](const Proposal& p) { return p.arm_m > o.max_torque_arm_m; };
  std::stable_partition(proposals.begin(), proposals.end(),
                        [&](const Proposal& p) { return !unbalanced(p); });

  // Built for the first grasp about to be kept: most proposals never need it.
  std::optional<OcclusionMap> occlusion;
  const auto way_in_seen = [&](const Hand& grasp) {
    if (o.unseen_is_free) return true;
    if (!occlusion) occlusion.emplace(*in.cloud, float(o.point_radius_m));
    return way_in_is_seen(grasp, g, *occlusion, o.standoff_m, float(o.occlusion_margin_m));
  };

  // Built for the first grasp about to be kept, with a robot only.
  std::optional<collision::ArmCollisionWorld> arm_world;
  const auto arm_rejection = [&](const Hand& grasp) {
    if (!arm) return Rejection::kNone;
    const auto start = std::chrono::steady_clock::now();
    if (!arm_world) arm_world.emplace(arm->world_for(context.scene ? *context.scene : *in.cloud));
    const Rejection why = arm->check(*arm_world, grasp, o.standoff_m, context.start);
    if (context.times != nullptr)
      context.times->reach_s +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return why;
  };

  const std::int32_t target = object_of_interest(in, o);
  std::map<std::int32_t, std::size_t> per_object;
  const auto object_rejection = [&](const Hand& grasp) {
    if (target != kAnyObject && (target < 0 || grasp.object != target))
      return Rejection::kOtherObject;
    if (o.grasps_per_object > 0 && grasp.object >= 0 &&
        per_object[grasp.object] >= o.grasps_per_object)
      return Rejection::kNotSelected;
    return Rejection::kNone;
  };

  // The kept grasps first, then the proposals not kept, then the input hands.
  std::vector<Hand> kept, dropped;
  std::vector<std::pair<const Proposal*, bool>> placed;  // proposal, kept?
  // Whether a balanced grasp was kept: in all, or per object when grasps are chosen per
  // object (an object whose only grasps are unbalanced still gets one).
  bool balanced_kept = false;
  std::map<std::int32_t, bool> balanced_on;
  const auto balanced_before = [&](const Hand& grasp) {
    return o.grasps_per_object > 0 ? balanced_on[grasp.object] : balanced_kept;
  };
  for (const Proposal& p : proposals) {
    context.stop.throw_if_stop_requested("cluster_selector");
    Hand grasp = p.grasp;
    grasp.rejection = Rejection::kNone;
    if (unbalanced(p) && balanced_before(grasp))
      grasp.rejection = Rejection::kUnbalanced;
    else if (const Rejection why = object_rejection(grasp); why != Rejection::kNone)
      grasp.rejection = why;
    else if (kept.size() >= o.max_grasps)
      grasp.rejection = Rejection::kNotSelected;
    else if (!approach_is_free(grasp, g, *in.cloud, o.standoff_m) || !way_in_seen(grasp))
      grasp.rejection = Rejection::kInCollision;
    else
      grasp.rejection = arm_rejection(grasp);
    if (grasp.rejection == Rejection::kNone && !unbalanced(p))
      balanced_kept = balanced_on[grasp.object] = true;
    if (grasp.rejection == Rejection::kNone) ++per_object[grasp.object];
    placed.emplace_back(&p, grasp.rejection == Rejection::kNone);
    (grasp.rejection == Rejection::kNone ? kept : dropped).push_back(std::move(grasp));
  }
  for (Hand& grasp : kept)
    if (grasp.closing_points.empty())
      grasp.closing_points =
          points_in_closing_region(f.body, grasp.X_FrameHand, in.cloud->points_m);
  std::size_t next_kept = 0, next_dropped = kept.size();
  for (const auto& [proposal, was_kept] : placed) {
    const std::int32_t index = std::int32_t(was_kept ? next_kept++ : next_dropped++);
    for (std::size_t m : proposal->members) {
      hands[m].rejection = Rejection::kClustered;
      hands[m].merged_into = index;
    }
  }
  // A grasp's score is its cluster's sum (an order, not a probability, whatever the input's).
  HandSet out{in.cloud, std::move(kept), g, in.support, in.objects};
  out.hands.insert(out.hands.end(), dropped.begin(), dropped.end());
  out.hands.insert(out.hands.end(), hands.begin(), hands.end());
  return out;
}

}  // namespace

HandSet ClusterSelector::screen(const HandSet& in, const SelectionContext& context) const {
  if (!in.cloud) throw Error("cluster_selector: the hand set has no cloud");
  context.stop.throw_if_stop_requested("cluster_selector");
  HandSet out = in;
  check_each(out.hands, in, fixtures_of(in, options_), options_, TipsCheck::kLeaveForSelection);
  return out;
}

HandSet ClusterSelector::select(const HandSet& in, const SelectionContext& context) const {
  if (!in.cloud) throw Error("cluster_selector: the hand set has no cloud");
  const Fixtures f = fixtures_of(in, options_);
  std::vector<Hand> hands = in.hands;
  const std::vector<double> held = check_each(hands, in, f, options_);
  HandSet out = choose(hands, held, in, f, options_, arm_.get(), context);
  const bool chosen = !out.hands.empty() && out.hands.front().rejection == Rejection::kNone;
  if (chosen || !options_.fingertip_last_resort) return out;
  // No other grasp: the hands widest beyond the fingertips are tried after all. An attempt
  // that may push the object out beats none (it may also leave it in a better pose).
  bool relaxed = false;
  for (Hand& hand : hands)
    if (hand.rejection == Rejection::kWidestBeyondTheTips)
      hand.rejection = Rejection::kNone, relaxed = true;
  return relaxed ? choose(std::move(hands), held, in, f, options_, arm_.get(), context) : out;
}

}  // namespace antipode::selectors
