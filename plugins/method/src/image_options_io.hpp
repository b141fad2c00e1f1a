#pragma once
// HandImageOptions in antipode's binary files (training sets and classifier models), field by
// field so that the bytes depend only on the values. Internal to the library.

#include <cstdint>

#include "antipode/core/binary_file.hpp"
#include "antipode/grasp/hand_image.hpp"

namespace antipode::detail {

inline void put_image_options(BinaryWriter& w, const HandImageOptions& o) {
  for (const int v : {o.cells_along, o.cells_across, o.cell_px, o.block_cells, o.bins,
                      o.point_radius_px, o.normal_features ? 1 : 0, o.occlusion_features ? 1 : 0}) {
    w.put<std::int32_t>(v);
  }
}

/// Reads what put_image_options() wrote; the values are checked by the caller (validate()).
inline HandImageOptions get_image_options(BinaryReader& r) {
  HandImageOptions o;
  for (int* v :
       {&o.cells_along, &o.cells_across, &o.cell_px, &o.block_cells, &o.bins, &o.point_radius_px}) {
    *v = r.get<std::int32_t>();
  }
  const auto normal_features = r.get<std::int32_t>();
  if (normal_features != 0 && normal_features != 1) r.fail("normal_features flag is not 0 or 1");
  o.normal_features = normal_features == 1;
  const auto occlusion_features = r.get<std::int32_t>();
  if (occlusion_features != 0 && occlusion_features != 1) {
    r.fail("occlusion_features flag is not 0 or 1");
  }
  o.occlusion_features = occlusion_features == 1;
  return o;
}

}  // namespace antipode::detail
