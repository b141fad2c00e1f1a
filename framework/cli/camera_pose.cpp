#include "camera_pose.hpp"

#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "antipode/core/error.hpp"
#include "antipode/core/input_file.hpp"

namespace antipode::cli {
namespace {

constexpr const char* kForm =
    "--camera-pose takes 'x y z qw qx qy qz' (metres, a unit quaternion) or an extrinsics "
    "YAML file with translation_m: [x, y, z] and quaternion_wxyz: [qw, qx, qy, qz]";

// The numbers of `text`, separated by spaces or commas; nothing if a word is no number.
std::optional<std::vector<double>> numbers_in(std::string text) {
  for (char& c : text)
    if (c == ',') c = ' ';
  std::istringstream in(text);
  std::vector<double> numbers;
  for (std::string word; in >> word;) {
    std::size_t used = 0;
    try {
      numbers.push_back(std::stod(word, &used));
    } catch (const std::exception&) {
      return std::nullopt;
    }
    if (used != word.size()) return std::nullopt;
  }
  return numbers;
}

// A list of `count` numbers at `key` of the extrinsics file `path`.
std::vector<double> numbers_at(const YAML::Node& file, const char* key, std::size_t count,
                               const std::string& path) {
  const YAML::Node node = file[key];
  if (!node) throw Error(std::string("the extrinsics file has no '") + key + "'", {path});
  std::vector<double> numbers;
  try {
    numbers = node.as<std::vector<double>>();
  } catch (const YAML::Exception&) {
    throw Error(std::string("'") + key + "' must be a list of numbers", {path});
  }
  if (numbers.size() != count) {
    throw Error(std::string("'") + key + "' must have " + std::to_string(count) + " numbers, got " +
                    std::to_string(numbers.size()),
                {path});
  }
  return numbers;
}

CameraPose from_file(const std::string& path) {
  require_regular_file(path, "an extrinsics YAML file");
  YAML::Node file;
  try {
    file = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw Error("not YAML: " + e.msg, {path, e.mark.line + 1, e.mark.column + 1});
  }
  if (!file.IsMap()) throw Error("an extrinsics file must be a mapping", {path});
  for (const auto& entry : file) {
    const std::string key = entry.first.as<std::string>();
    if (key != "translation_m" && key != "quaternion_wxyz" && key != "frame")
      throw Error("unknown key '" + key + "' (use translation_m, quaternion_wxyz, frame)", {path});
  }
  const std::vector<double> t = numbers_at(file, "translation_m", 3, path);
  const std::vector<double> q = numbers_at(file, "quaternion_wxyz", 4, path);
  CameraPose pose;
  pose.xyz_wxyz = {t[0], t[1], t[2], q[0], q[1], q[2], q[3]};
  if (file["frame"]) pose.frame = file["frame"].as<std::string>();
  return pose;
}

}  // namespace

std::string yaml_list(const double* values, std::size_t count) {
  std::ostringstream out;
  out.precision(17);
  out << "[";
  for (std::size_t i = 0; i < count; ++i) out << (i ? ", " : "") << values[i];
  out << "]";
  return out.str();
}

std::string CameraPose::port_text() const { return yaml_list(xyz_wxyz.data(), xyz_wxyz.size()); }

CameraPose read_camera_pose(const std::string& text) {
  const auto numbers = numbers_in(text);
  CameraPose pose;
  if (numbers && numbers->size() == 7) {
    for (std::size_t i = 0; i < 7; ++i) pose.xyz_wxyz[i] = (*numbers)[i];
  } else if (std::filesystem::exists(text)) {
    pose = from_file(text);
  } else if (const auto dot = text.rfind('.');
             dot != std::string::npos &&
             (text.substr(dot) == ".yaml" || text.substr(dot) == ".yml")) {
    throw Error("--camera-pose: no such extrinsics file: " + text);
  } else {
    throw Error(std::string(kForm) + "; got '" + text + "'");
  }
  double norm = 0.0;
  for (std::size_t i = 0; i < 7; ++i) {
    if (!std::isfinite(pose.xyz_wxyz[i])) throw Error("--camera-pose: a number is not finite");
    if (i >= 3) norm += pose.xyz_wxyz[i] * pose.xyz_wxyz[i];
  }
  if (std::abs(std::sqrt(norm) - 1.0) > 1e-3) {
    throw Error("--camera-pose: the quaternion [qw, qx, qy, qz] has norm " +
                std::to_string(std::sqrt(norm)) + "; it must be 1 (a rotation)");
  }
  return pose;
}

}  // namespace antipode::cli
