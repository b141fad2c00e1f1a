#include "bench_objects.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

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

std::vector<BenchObject> mesh_objects(const std::string& folder) {
  if (!fs::is_directory(folder))
    throw Error("--objects: '" + folder + "' is neither 'procedural' nor a folder of meshes");
  const std::string absolute = fs::absolute(folder).lexically_normal().string();
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.is_directory() && fs::exists(entry.path() / "visual.obj"))
      names.push_back(entry.path().filename().string());
    else if (entry.is_regular_file() && entry.path().extension() == ".obj")
      names.push_back(entry.path().stem().string());
  }
  if (names.empty())
    throw Error("--objects: '" + folder + "' holds no mesh (NAME/visual.obj or NAME.obj)");
  std::sort(names.begin(), names.end());
  std::vector<BenchObject> objects;
  for (const auto& name : names)
    objects.push_back({name, "mesh: '" + name + "', folder: '" + absolute + "'", true});
  return objects;
}

}  // namespace

std::vector<BenchObject> bench_objects(const std::string& which, const std::string& procedural_file,
                                       double min_width_m, double max_width_m) {
  if (which == "procedural") return procedural_objects(procedural_file, min_width_m, max_width_m);
  return mesh_objects(which);
}

Eigen::Vector3d pose_rpy(int k, int poses) {
  const double yaw = 2.0 * M_PI * double(k) / double(std::max(1, poses));
  return {k % 2 == 1 ? M_PI / 2 : 0.0, 0.0, yaw};
}

}  // namespace antipode::cli
