#include <algorithm>
#include <cstdio>
#include <iostream>

#include "antipode/bt/loader.hpp"
#include "antipode/core/error.hpp"
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

}  // namespace

int detect_command(const DetectOptions& options) {
  Session session = open_session();
  bt::Tree tree =
      load_tree_for(session, options.tree_path, detect_entries(options), options.settings);
  const Tracing tracing = attach_tracers(tree, options.settings.verbose, "");
  const bt::Status status = tree.tick_while_running();
  if (const auto* hands = tree.blackboard().find(options.hands_entry)) {
    if (const auto* set = std::any_cast<HandSetPtr>(hands); set != nullptr && *set) {
      print_summary(**set, 5);
    }
  }
  std::cout << options.tree_path << ": " << bt::to_string(status) << "\n";
  return status == bt::Status::kSuccess ? kExitSuccess : kExitTreeFailed;
}

}  // namespace antipode::cli
