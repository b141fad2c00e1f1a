#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "antipode/bt/loader.hpp"
#include "antipode/core/atomic_file.hpp"
#include "antipode/core/error.hpp"
#include "antipode/geometry/scene_layout.hpp"
#include "antipode/interfaces/grasp_selector.hpp"
#include "antipode/interfaces/hand_set.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "session.hpp"

namespace antipode::cli {
namespace {

// The detect tree reads these entries, which `antipode detect` fills from its arguments.
std::vector<std::string> detect_entries(const DetectOptions& options) {
  return {"cloud_file=" + options.cloud_path, "grasps_file=" + options.out_path,
          "image_file=" + options.image_path};
}

void print_summary(const HandSet& set, std::size_t count) {
  std::vector<const Hand*> hands;
  for (const Hand& hand : set.hands) {
    if (hand.rejection == Rejection::kNone) hands.push_back(&hand);
  }
  std::stable_sort(hands.begin(), hands.end(),
                   [](const Hand* a, const Hand* b) { return a->score > b->score; });
  std::cout << hands.size() << " grasps";
  if (set.cloud) std::cout << " in frame '" << set.cloud->frame << "'";
  std::cout << (hands.empty() ? "\n" : "; the first by score:\n");
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
// once classified) and where the best grasps lie.
void print_explanation(const HandSet* sampled, const HandSet* screened, const HandSet* classified,
                       std::size_t best) {
  if (sampled == nullptr) {
    std::cout << "explain: no hand hypotheses (the tree failed at or before sampling)\n";
    return;
  }
  std::cout << "scene: "
            << (sampled->objects.empty() && sampled->support
                    ? "a support plane, no segmentation (objects: all)"
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
  std::stable_sort(grasps.begin(), grasps.end(),
                   [](const Hand* a, const Hand* b) { return a->score > b->score; });
  grasps.resize(std::min(best, grasps.size()));
  const auto on_objects = std::count_if(grasps.begin(), grasps.end(),
                                        [](const Hand* hand) { return hand->object >= 0; });
  std::cout << "the " << grasps.size() << " best grasps: " << on_objects << " on objects\n";
}

}  // namespace

int detect_command(const DetectOptions& options) {
  for (const std::string* path : {&options.out_path, &options.image_path})
    if (!path->empty()) check_output_path(*path);  // before the work, and before either is written
  const std::vector<std::string> entries = detect_entries(options);
  Session session = open_session_for(options.tree_path, entries, options.settings);
  bt::Tree tree = load_tree_for(session, options.tree_path, entries, options.settings);
  const Tracing tracing = attach_tracers(tree, options.settings.verbose, "");
  const bt::Status status = tree.tick_while_running();
  if (const HandSet* set = hand_set(tree, options.hands_entry)) print_summary(*set, 5);
  if (options.explain)
    print_explanation(hand_set(tree, "hands"), hand_set(tree, "screened"),
                      hand_set(tree, options.hands_entry), 12);
  std::cout << result_line(options.tree_path, status, tracing) << "\n";
  return status == bt::Status::kSuccess ? kExitSuccess : kExitTreeFailed;
}

}  // namespace antipode::cli
