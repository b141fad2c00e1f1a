#include "bench_objects.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "antipode/core/error.hpp"

namespace fs = std::filesystem;

namespace antipode::cli {
namespace {

std::string flow_list(const YAML::Node& list) {
  std::string text = "[";
  for (std::size_t i = 0; i < list.size(); ++i) text += (i ? ", " : "") + list[i].as<std::string>();
  return text + "]";
}

std::vector<BenchObject> procedural_objects(const std::string& file, double min_width_m,
                                            double max_width_m) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(file);
  } catch (const YAML::Exception& error) {
    throw Error("procedural test set '" + file + "': " + error.what());
  }
  const YAML::Node list = root["objects"];
  if (!list.IsSequence() || list.size() == 0)
    throw Error("procedural test set '" + file + "' lists no 'objects'");
  std::vector<BenchObject> objects;
  for (const YAML::Node& item : list) {
    try {
      BenchObject object;
      object.name = item["name"].as<std::string>();
      object.spec_yaml =
          "shape: " + item["shape"].as<std::string>() + ", size_m: " + flow_list(item["size_m"]);
      const double width = item["graspable_width_m"].as<double>();
      object.graspable = width >= min_width_m && width <= max_width_m;
      objects.push_back(std::move(object));
    } catch (const YAML::Exception&) {
      throw Error("procedural test set '" + file + "', object " +
                  std::to_string(objects.size() + 1) +
                  ": needs name, shape, size_m and graspable_width_m");
    }
  }
  return objects;
}

// The smallest extent of the bounding box of the vertices of the OBJ file at `path`: the
// width a gripper must span at least (a mug 8 cm across in every direction cannot be held by
// a 7 cm gripper, whatever the detector does).
double smallest_extent(const fs::path& path) {
  std::ifstream file(path);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e30), hi = -lo;
  for (std::string line; std::getline(file, line);) {
    if (line.size() < 2 || line[0] != 'v' || line[1] != ' ') continue;
    std::istringstream fields(line.substr(2));
    Eigen::Vector3d v;
    if (fields >> v.x() >> v.y() >> v.z()) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  }
  if ((hi.array() < lo.array()).any()) throw Error("mesh '" + path.string() + "' has no vertex");
  return (hi - lo).minCoeff();
}

std::vector<BenchObject> mesh_objects(const std::string& folder, double min_width_m,
                                      double max_width_m) {
  if (!fs::is_directory(folder))
    throw Error("--objects: '" + folder + "' is neither 'procedural' nor a folder of meshes");
  const std::string absolute = fs::absolute(folder).lexically_normal().string();
  std::vector<std::pair<std::string, fs::path>> meshes;  // name, file
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.is_directory() && fs::exists(entry.path() / "visual.obj"))
      meshes.emplace_back(entry.path().filename().string(), entry.path() / "visual.obj");
    else if (entry.is_regular_file() && entry.path().extension() == ".obj")
      meshes.emplace_back(entry.path().stem().string(), entry.path());
  }
  if (meshes.empty())
    throw Error("--objects: '" + folder + "' holds no mesh (NAME/visual.obj or NAME.obj)");
  std::sort(meshes.begin(), meshes.end());
  std::vector<BenchObject> objects;
  for (const auto& [name, file] : meshes) {
    const double width = smallest_extent(file);
    objects.push_back({name, "mesh: '" + name + "', folder: '" + absolute + "'",
                       width >= min_width_m && width <= max_width_m});
  }
  return objects;
}

}  // namespace

std::vector<BenchObject> bench_objects(const std::string& which, const std::string& procedural_file,
                                       double min_width_m, double max_width_m) {
  if (which == "procedural") return procedural_objects(procedural_file, min_width_m, max_width_m);
  return mesh_objects(which, min_width_m, max_width_m);
}

Eigen::Vector3d pose_rpy(int k, int poses) {
  const double yaw = 2.0 * M_PI * double(k) / double(std::max(1, poses));
  return {k % 2 == 1 ? M_PI / 2 : 0.0, 0.0, yaw};
}

}  // namespace antipode::cli
