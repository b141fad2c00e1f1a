#pragma once
// The table_top_selector component: the simplest grasp choice for a table-top cell.

#include "antipode/core/hand_geometry.hpp"
#include "antipode/core/parameters.hpp"
#include "antipode/interfaces/grasp_selector.hpp"

namespace antipode::cells {

/// Ranks the hands no stage rejected by score (best first), keeping only those whose body
/// stays above the table plane both at the grasp and `standoff_m` back along the approach,
/// where a cell starts its approach. No clustering, no reachability: a baseline for
/// pipelines without a classifier ("NC" in the paper).
class TableTopSelector final : public GraspSelector {
 public:
  /// Parameters: table_z_m (required), standoff_m (0.1), clearance_m (0.003), max_grasps
  /// (10). Throws antipode::Error for unknown or invalid ones.
  explicit TableTopSelector(const Parameters& params);

  std::vector<Hand> select(const HandSet& hands) const override;

  /// True when the hand's bounding box clears the table at the grasp and the stand-off pose.
  bool clears_table(const Hand& hand) const;

 private:
  HandGeometry geometry_;
  double table_z_m_ = 0.0;
  double standoff_m_ = 0.1;
  double clearance_m_ = 0.003;
  double palm_thickness_m_ = 0.02;
  std::size_t max_grasps_ = 10;
};

}  // namespace antipode::cells
