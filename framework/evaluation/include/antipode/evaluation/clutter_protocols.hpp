#pragma once
// The dense-clutter protocols `antipode bench clutter --protocol` runs, with the published
// figures each is compared with (../shared/reference/anchors.md).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace antipode::evaluation {

/// A published result: who, grasp success and objects removed (percent; < 0 = not given).
struct PublishedClutterResult {
  std::string who;
  double success_pct;
  double removed_pct;
};

struct ClutterProtocol {
  std::string name;          ///< "paper", "vgn-pile", "vgn-packed"
  std::string tree;          ///< the tree the bench runs unless --tree says otherwise
  std::string scene;         ///< the cell's scene ("" = the tree's)
  int objects_per_run;       ///< unless --objects-per-run says otherwise
  std::string success_name;  ///< what the protocol calls successes / attempts
  std::string removed_name;  ///< ... and removed / the objects in the cell at the start
  std::vector<PublishedClutterResult> published;
};

/// The protocol called `name`; throws antipode::Error listing the known ones otherwise.
const ClutterProtocol& clutter_protocol(const std::string& name);

/// The protocol a clutter bench's report names (its "protocol" entry; "paper" without one);
/// throws antipode::Error, naming the report's entry, for one that is not a known name.
const ClutterProtocol& report_protocol(const nlohmann::ordered_json& report);

}  // namespace antipode::evaluation
