#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "antipode/bt/loader.hpp"
#include "antipode/core/atomic_file.hpp"
#include "antipode/core/error.hpp"
#include "antipode/evaluation/exit_codes.hpp"
#include "antipode/evaluation/session.hpp"
#include "antipode/geometry/scene_layout.hpp"
#include "antipode/interfaces/grasp_selector.hpp"
#include "antipode/interfaces/hand_set.hpp"
#include "camera_pose.hpp"
#include "commands.hpp"

namespace antipode::cli {

namespace {

// The detect tree reads these entries, which `antipode detect` fills from its arguments.
std::vector<std::string> detect_entries(const DetectOptions& options,
                                        const std::optional<CameraPose>& pose) {
  std::vector<std::string> entries = {"cloud_file=" + options.cloud_path,
                                      "grasps_file=" + options.out_path,
                                      "image_file=" + options.image_path};
  std::string frame = options.frame;
  if (frame.empty()) frame = pose ? (pose->frame.empty() ? "base" : pose->frame) : "sensor";
  entries.push_back("frame=" + frame);
  if (pose) entries.push_back("camera_pose=" + pose->port_text());
  if (options.rejected) entries.emplace_back("include_rejected=true");
  return entries;
}

// The command's options as the tree's settings, before the user's own --set entries (which
// may override them): a camera pose makes the frame's z axis the support's up; --top and
// --per-object run the tree detect_top with the selector's limits; --workspace crops the cloud.
TreeRunSettings detect_settings(const DetectOptions& options, bool has_pose) {
  TreeRunSettings settings = options.settings;
  std::vector<std::string> ours;
  if (has_pose) ours.push_back("sampler.scene.up=[0, 0, 1]");
  if (options.top > 0 || options.per_object > 0) {
    if (settings.main_tree.empty()) settings.main_tree = "detect_top";
    ours.push_back("selector.max_grasps=" +
                   std::to_string(options.top > 0 ? options.top : 1000000));  // no --top: all
    ours.push_back("selector.grasps_per_object=" + std::to_string(options.per_object));
  }
  if (options.workspace.size() == 6) {
    const double* w = options.workspace.data();
    for (int axis = 0; axis < 3; ++axis) {
      if (!(w[axis] < w[axis + 3]))
        throw Error("--workspace: the minimum " + std::string(1, "xyz"[axis]) +
                    " must be below the maximum (XMIN YMIN ZMIN XMAX YMAX ZMAX)");
    }
    ours.push_back("sampler.workspace.min=" + yaml_list(w, 3));
    ours.push_back("sampler.workspace.max=" + yaml_list(w + 3, 3));
  }
  settings.set.insert(settings.set.begin(), ours.begin(), ours.end());
  return settings;
}

// The grasps of `set`: a selection's in their rank (`ranked`), others best score first.
void print_summary(const HandSet& set, std::size_t count, bool ranked) {
  std::vector<const Hand*> hands;
  for (const Hand& hand : set.hands) {
    if (hand.rejection == Rejection::kNone) hands.push_back(&hand);
  }
  if (!ranked) {
    std::stable_sort(hands.begin(), hands.end(),
                     [](const Hand* a, const Hand* b) { return a->score > b->score; });
  }
  std::cout << hands.size() << " grasps";
  if (set.cloud) std::cout << " in frame '" << set.cloud->frame << "'";
  std::cout << (hands.empty() ? "\n"
                : ranked      ? "; the first by rank:\n"
                              : "; the first by score:\n");
  for (std::size_t i = 0; i < std::min(count, hands.size()); ++i) {
    const Hand& hand = *hands[i];
    const Eigen::Vector3d p = hand.position_m(), a = hand.approach();
    std::printf(
        "  position [%.3f %.3f %.3f] m  approach [%.2f %.2f %.2f]  width %.3f m  "
        "score %.3f\n",
        p.x(), p.y(), p.z(), a.x(), a.y(), a.z(), hand.width_m, hand.score);
  }
}

const HandSet* hand_set(const bt::Tree& tree, const std::string& entry) {
  if (const auto* value = tree.blackboard().find(entry)) {
    if (const auto* set = std::any_cast<HandSetPtr>(value); set != nullptr && *set)
      return set->get();
  }
  return nullptr;
}

// "#0 120, #1 40, no object 3": hands per object id.
std::string per_object(const HandSet& set, bool grasps_only) {
  std::map<std::int32_t, std::size_t> count;
  for (const Hand& hand : set.hands) {
    if (!grasps_only || hand.label == HandLabel::kPositive) ++count[hand.object];
  }
  std::string text;
  for (const auto& [object, n] : count) {
    text += (text.empty() ? "" : ", ") +
            (object < 0 ? std::string("no object") : "#" + std::to_string(object)) + " " +
            std::to_string(n);
  }
  return text.empty() ? "none" : text;
}

// What --explain prints: the scene the sampler found, how many hands each stage kept (per
// object; the screen's reasons, when the tree screens into {screened}, and every rejection's
// once classified) and where the best grasps lie: the selection's grasps when the tree
// selected (`selection`), else the `best` best scores among the grasps classified.
void print_explanation(const HandSet* sampled, const HandSet* screened, const HandSet* classified,
                       const HandSet* selection, std::size_t best) {
  if (sampled == nullptr) {
    std::cout << "explain: no hand hypotheses (the tree failed at or before sampling)\n";
    return;
  }
  std::cout << "scene: "
            << (sampled->objects.empty() && sampled->support
                    ? "a support plane, no segmentation (objects: all)"
                : sampled->cloud
                    ? describe_scene(sampled->support, sampled->objects, sampled->cloud->points_m)
                    : describe_scene(sampled->support, sampled->objects))
            << "\n";
  std::cout << "hypotheses: " << sampled->hands.size()
            << " (per object: " << per_object(*sampled, false) << ")\n";
  if (screened != nullptr) {
    const auto left = std::count_if(screened->hands.begin(), screened->hands.end(),
                                    [](const Hand& hand) { return selectable(hand); });
    std::cout << "left to classify by the selector's screen: " << left << " ("
              << rejection_counts(screened->hands, false) << ")\n";
  }
  if (classified == nullptr) return;
  std::vector<const Hand*> grasps;
  for (const Hand& hand : classified->hands) {
    if (hand.label == HandLabel::kPositive) grasps.push_back(&hand);
  }
  std::cout << "classified as grasps: " << grasps.size()
            << " (per object: " << per_object(*classified, true) << ")\n";
  std::cout << "rejected by the screen or the classifier: "
            << rejection_counts(classified->hands, false) << "\n";
  if (selection != nullptr) {
    grasps.clear();
    for (const Hand& hand : selection->hands)
      if (hand.rejection == Rejection::kNone) grasps.push_back(&hand);
  } else {
    std::stable_sort(grasps.begin(), grasps.end(),
                     [](const Hand* a, const Hand* b) { return a->score > b->score; });
    grasps.resize(std::min(best, grasps.size()));
  }
  const auto on_objects = std::count_if(grasps.begin(), grasps.end(),
                                        [](const Hand* hand) { return hand->object >= 0; });
  std::cout << "the " << grasps.size() << (selection != nullptr ? " selected" : " best")
            << " grasps: " << on_objects << " on objects\n";
}

// Where to see every hand in 3D, with why each dropped one was dropped (docs/viewer.md).
void print_view_hint(const DetectOptions& options) {
  const std::string out = options.out_path.empty() ? "grasps.json" : options.out_path;
  std::cout << "see every hand in 3D: ";
  if (options.out_path.empty())
    std::cout << "add --out " << out << " --rejected, then ";
  else if (!options.rejected)
    std::cout << "add --rejected, then ";
  std::cout << "antipode view " << options.cloud_path << " " << out << " --open\n";
}

}  // namespace

int detect_command(const DetectOptions& options) {
  for (const std::string* path : {&options.out_path, &options.image_path})
    if (!path->empty()) check_output_path(*path);  // before the work, and before either is written
  std::optional<CameraPose> pose;
  if (!options.camera_pose.empty()) pose = read_camera_pose(options.camera_pose);
  if (options.rejected && options.out_path.empty())
    throw Error("--rejected: the rejected hands are written to --out, which names no file");
  const std::vector<std::string> entries = detect_entries(options, pose);
  const TreeRunSettings settings = detect_settings(options, pose.has_value());
  Session session = open_session_for(options.tree_path, entries, settings);
  bt::Tree tree = load_tree_for(session, options.tree_path, entries, settings);
  const Tracing tracing = attach_tracers(tree, settings.verbose, "");
  const bt::Status status = tree.tick_while_running();
  const bool ranked = settings.main_tree == "detect_top";
  if (const HandSet* set = hand_set(tree, options.hands_entry)) print_summary(*set, 5, ranked);
  if (options.explain) {
    const HandSet* classified = hand_set(tree, "classified");  // detect_top's, before selection
    const HandSet* written = hand_set(tree, options.hands_entry);
    print_explanation(hand_set(tree, "hands"), hand_set(tree, "screened"),
                      classified != nullptr ? classified : written, ranked ? written : nullptr, 12);
    print_view_hint(options);
  }
  std::cout << result_line(options.tree_path, status, tracing) << "\n";
  return status == bt::Status::kSuccess ? kExitSuccess : kExitTreeFailed;
}

}  // namespace antipode::cli
