#include "antipode/evaluation/bench_objects.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <Eigen/Geometry>
#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "antipode/core/error.hpp"
#include "antipode/geometry/narrowest_extent.hpp"

namespace fs = std::filesystem;

namespace antipode::evaluation {
namespace {

std::string flow_list(const YAML::Node& list) {
  std::string text = "[";
  for (std::size_t i = 0; i < list.size(); ++i) text += (i ? ", " : "") + list[i].as<std::string>();
  return text + "]";
}

std::vector<BenchObject> procedural_objects(const std::string& file) {
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
      object.width_m = item["graspable_width_m"].as<double>();
      objects.push_back(std::move(object));
    } catch (const YAML::Exception&) {
      throw Error("procedural test set '" + file + "', object " +
                  std::to_string(objects.size() + 1) +
                  ": needs name, shape, size_m and graspable_width_m");
    }
  }
  return objects;
}

// The vertices of the OBJ file at `path`.
std::vector<Eigen::Vector3d> obj_vertices(const fs::path& path) {
  std::ifstream file(path);
  std::vector<Eigen::Vector3d> vertices;
  for (std::string line; std::getline(file, line);) {
    if (line.size() < 2 || line[0] != 'v' || line[1] != ' ') continue;
    std::istringstream fields(line.substr(2));
    Eigen::Vector3d v;
    if (fields >> v.x() >> v.y() >> v.z()) vertices.push_back(v);
  }
  if (vertices.empty()) throw Error("mesh '" + path.string() + "' has no vertex");
  return vertices;
}

std::vector<BenchObject> mesh_objects(const std::string& folder) {
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
    std::string spec = "mesh: '" + name + "', folder: '";
    spec.append(absolute).append("'");
    BenchObject object{name, spec, 0.0, nullptr};
    auto vertices = std::make_shared<const std::vector<Eigen::Vector3d>>(obj_vertices(file));
    Eigen::Vector3d lo = vertices->front(), hi = lo;
    for (const auto& v : *vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    object.width_m = (hi - lo).minCoeff();
    object.vertices = std::move(vertices);
    objects.push_back(std::move(object));
  }
  return objects;
}

}  // namespace

std::vector<BenchObject> bench_objects(const std::string& which,
                                       const std::string& procedural_file) {
  if (which == "procedural") return procedural_objects(procedural_file);
  return mesh_objects(which);
}

bool BenchObject::graspable_in_pose(int k, int poses, double min_width_m,
                                    double max_width_m) const {
  if (!vertices) return width_m >= min_width_m && width_m <= max_width_m;
  const Eigen::Vector3d rpy = pose_rpy(k, poses);
  const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  std::vector<Eigen::Vector3d> placed;
  placed.reserve(vertices->size());
  for (const auto& v : *vertices) placed.push_back(rotation * v);
  const double narrowest = narrowest_horizontal_extent_m(placed);
  return narrowest >= min_width_m && narrowest <= max_width_m;
}

Eigen::Vector3d pose_rpy(int k, int poses) {
  const double yaw = 2.0 * M_PI * double(k) / double(std::max(1, poses));
  return {k % 2 == 1 ? M_PI / 2 : 0.0, 0.0, yaw};
}

}  // namespace antipode::evaluation
