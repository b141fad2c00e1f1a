#pragma once
// Internal to the io area: coordinates out of PCL's untyped cloud.

#include <string>
#include <vector>

#include <pcl/PCLPointCloud2.h>
#include <Eigen/Core>

namespace antipode::io {

/// The x, y, z values (float32 or float64 fields) of every point of `blob`, non-finite ones
/// included. Throws Error naming `path` when a coordinate field is missing or not floating
/// point, or when the blob's data is shorter than its dimensions say.
std::vector<Eigen::Vector3f> coordinates_of(const std::string& path,
                                            const pcl::PCLPointCloud2& blob);

}  // namespace antipode::io
