#include "antipode/io/load_cloud.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "antipode/core/error.hpp"
#include "antipode/core/input_file.hpp"
#include "raw_points.hpp"

namespace antipode {
namespace io {

std::string read_file_bytes(const std::string& path) {
  require_regular_file(path, "a .pcd or .ply file");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw Error(std::string("cannot open cloud file: ") + std::strerror(errno), {path});
  std::string bytes;
  file.seekg(0, std::ios::end);
  const std::streamoff size = file.tellg();
  if (size < 0) throw Error("cannot read cloud file (is it a directory?)", {path});
  bytes.resize(static_cast<std::size_t>(size));
  file.seekg(0, std::ios::beg);
  if (size > 0 && !file.read(bytes.data(), size)) throw Error("cannot read cloud file", {path});
  return bytes;
}

}  // namespace io

namespace {

std::string lower_extension(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

io::RawPoints read_any(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext != "pcd" && ext != "ply") {
    const std::string format = ext.empty() ? "no extension" : "unknown extension '." + ext + "'";
    throw Error("cannot tell the cloud format: " + format + " (expected .pcd or .ply)", {path});
  }
  const std::string bytes = io::read_file_bytes(path);
  if (bytes.empty()) throw Error("the cloud file is empty", {path});
  return ext == "pcd" ? io::read_pcd(path, bytes) : io::read_ply(path, bytes);
}

}  // namespace

namespace {

// The finite points of `raw`, one view at the options' origin (else the file's), moved by
// X_ToFile.
Cloud cloud_of(const std::string& path, io::RawPoints raw, const LoadCloudOptions& options,
               const Eigen::Isometry3f& X_ToFile) {
  const Eigen::Vector3f origin =
      options.view_origin_m.value_or(raw.origin_m.value_or(Eigen::Vector3f::Zero()));
  if (raw.points_m.empty()) throw Error("the cloud has no points", {path});
  const std::size_t declared = raw.points_m.size();
  auto& points = raw.points_m;
  points.erase(std::remove_if(points.begin(), points.end(),
                              [](const Eigen::Vector3f& p) { return !p.allFinite(); }),
               points.end());
  if (points.empty()) {
    throw Error(
        "the cloud has no finite point (all " + std::to_string(declared) + " are NaN or infinite)",
        {path});
  }
  Cloud cloud;
  cloud.frame = options.frame;
  cloud.points_m = std::move(points);
  if (!X_ToFile.matrix().isIdentity()) {
    for (Eigen::Vector3f& p : cloud.points_m) p = X_ToFile * p;
  }
  cloud.view_masks.assign(cloud.points_m.size(), 1u);
  cloud.view_origins_m.push_back(X_ToFile * origin);
  return cloud;
}

}  // namespace

Cloud load_cloud(const std::string& path, const LoadCloudOptions& options) {
  return cloud_of(path, read_any(path), options, Eigen::Isometry3f::Identity());
}

std::vector<std::uint32_t> load_view_masks(const std::string& path) {
  io::RawPoints raw = read_any(path);
  std::vector<std::uint32_t> masks;
  if (raw.view_masks.size() != raw.points_m.size()) return masks;
  for (std::size_t i = 0; i < raw.points_m.size(); ++i)
    if (raw.points_m[i].allFinite()) masks.push_back(raw.view_masks[i]);  // as cloud_of keeps them
  return masks;
}

Cloud load_cloud_into(const std::string& path, const Eigen::Isometry3d& X_FrameFile,
                      const LoadCloudOptions& options, std::string* note) {
  if (!X_FrameFile.matrix().allFinite()) throw Error("the cloud's pose is not finite", {path});
  io::RawPoints raw = read_any(path);
  if (note != nullptr) {
    note->clear();
    const Eigen::Quaternionf& q = raw.rotation;
    if (!q.toRotationMatrix().isIdentity(1e-6f)) {
      *note = path + ": its VIEWPOINT rotation (qw qx qy qz " + std::to_string(q.w()) + " " +
              std::to_string(q.x()) + " " + std::to_string(q.y()) + " " + std::to_string(q.z()) +
              ") is not applied: the camera pose given is that of the frame its points are in";
    }
  }
  return cloud_of(path, std::move(raw), options, X_FrameFile.cast<float>());
}

}  // namespace antipode
