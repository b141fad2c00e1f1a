#include "antipode/evaluation/clutter_protocols.hpp"

#include "antipode/core/error.hpp"

namespace antipode::evaluation {

const ClutterProtocol& clutter_protocol(const std::string& name) {
  // The paper: ten objects dumped into a shallow box, Baxter with two views (section 5.3).
  // VGN / GIGA: five objects in a 30 cm workspace, one noisy view, a free-floating gripper;
  // their single-view noisy figures (VGN, CoRL 2020; GIGA, RSS 2021; Edge Grasp Network,
  // ICRA 2023).
  static const std::vector<ClutterProtocol> protocols = {
      {"paper",
       "trees/clear_box.yaml",
       "",
       10,
       "grasp success",
       "objects removed",
       {{"the paper (real Baxter)", 73.0, 85.0}}},
      {"vgn-pile",
       "trees/vgn_round.yaml",
       "scenes/vgn_pile.yaml",
       5,
       "GSR",
       "DR",
       {{"GPD", 17.7, 9.2},
        {"VGN", 60.7, 44.0},
        {"GIGA", 69.3, 49.8},
        {"GIGA (high resolution)", 69.8, 51.1},
        {"Edge Grasp Network", 89.9, 92.8},
        {"VN-Edge Grasp Network", 92.3, -1.0}}},
      {"vgn-packed",
       "trees/vgn_round.yaml",
       "scenes/vgn_packed.yaml",
       5,
       "GSR",
       "DR",
       {{"GPD", 35.4, 30.7},
        {"VGN", 74.5, 79.2},
        {"GIGA", 83.5, 84.3},
        {"GIGA (high resolution)", 87.9, 86.0},
        {"VN-Edge Grasp Network", 92.3, -1.0}}}};
  for (const ClutterProtocol& p : protocols)
    if (p.name == name) return p;
  throw Error("--protocol: unknown protocol '" + name + "' (paper, vgn-pile, vgn-packed)");
}

const ClutterProtocol& report_protocol(const nlohmann::ordered_json& report) {
  const auto entry = report.find("protocol");
  if (entry == report.end()) return clutter_protocol("paper");
  if (entry->is_string())
    for (const char* name : {"paper", "vgn-pile", "vgn-packed"})
      if (*entry == name) return clutter_protocol(name);
  throw Error("the report's \"protocol\" is " + entry->dump() +
              ", not one of \"paper\", \"vgn-pile\", \"vgn-packed\"");
}

}  // namespace antipode::evaluation
