#pragma once
/// @file
/// Axis-aligned boxes: workspaces and sample regions.

#include <Eigen/Core>

namespace antipode {

/// An axis-aligned box in a cloud's frame; both corners are inside (inclusive bounds).
struct AxisBox {
  Eigen::Vector3f min_m = Eigen::Vector3f::Constant(-1.0f);
  Eigen::Vector3f max_m = Eigen::Vector3f::Constant(1.0f);

  bool contains(const Eigen::Vector3f& p) const {
    return (p.array() >= min_m.array()).all() && (p.array() <= max_m.array()).all();
  }
  /// Throws antipode::Error unless both corners are finite and min <= max on every axis;
  /// `what` names the box in the message ("workspace", "sample region").
  void validate(const char* what = "box") const;
};

}  // namespace antipode
