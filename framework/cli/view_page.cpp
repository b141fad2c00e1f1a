#include "view_page.hpp"

// libb64's C header declares its functions without C linkage for C++.
extern "C" {
#include <b64/cencode.h>
}

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <vector>

#include "antipode/config.hpp"
#include "antipode/core/error.hpp"
#include "antipode/core/shipped_data.hpp"
#include "antipode/evaluation/json_file.hpp"
#include "antipode/io/gripper_file.hpp"
#include "antipode/io/load_cloud.hpp"

namespace antipode::cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

constexpr const char* kDataMark = "<!--antipode-data-->";

// Base64 of `size` bytes (libb64, fed in chunks that its int lengths hold), without the line
// breaks libb64 puts every 72 characters.
std::string base64(const void* bytes, std::size_t size) {
  constexpr std::size_t kChunk = std::size_t(3) << 20;
  std::vector<char> code(2 * kChunk);  // a chunk's code: 4/3 of it, and a break per 54 bytes
  std::string text;
  text.reserve(4 * (size / 3 + 1));
  base64_encodestate state;
  base64_init_encodestate(&state);
  const char* in = static_cast<const char*>(bytes);
  for (std::size_t done = 0; done < size; done += kChunk) {
    const int n = int(std::min(kChunk, size - done));
    text.append(code.data(), std::size_t(base64_encode_block(in + done, n, code.data(), &state)));
  }
  text.append(code.data(), std::size_t(base64_encode_blockend(code.data(), &state)));
  text.erase(std::remove(text.begin(), text.end(), '\n'), text.end());
  return text;
}

std::string extension_of(const std::string& path) {
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension;
}

Json cloud_json(const std::string& path) {
  const Cloud cloud = load_cloud(path);
  std::vector<float> xyz;
  xyz.reserve(3 * cloud.points_m.size());
  for (const Eigen::Vector3f& p : cloud.points_m) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  // load_cloud gives a file's cloud one view: the page colours it by height, not by view.
  return {{"count", cloud.points_m.size()}, {"points", base64(xyz.data(), 4 * xyz.size())}};
}

Json gripper_json(const std::string& path) {
  const GripperFile gripper = read_gripper_file(resolve_shipped(path));
  const HandGeometry& g = gripper.geometry;
  return {{"name", gripper.name},
          {"finger_width_m", g.finger_width_m},
          {"outer_diameter_m", g.outer_diameter_m},
          {"depth_m", g.depth_m},
          {"height_m", g.height_m},
          {"palm_thickness_m", g.palm_thickness_m},
          {"max_aperture_m", g.max_aperture_m}};
}

// The hands of a grasps file, with what the page draws and shows.
Json hands_json(const Json& grasps, const std::string& path) {
  const auto hands = grasps.find("hands");
  if (!grasps.is_object() || hands == grasps.end() || !hands->is_array())
    throw Error(path +
                ": not a grasps file (no \"hands\" list; `antipode detect --out` and "
                "WriteGrasps write one)");
  Json out = Json::array();
  for (std::size_t i = 0; i < hands->size(); ++i) {
    const Json& hand = (*hands)[i];
    const auto vector_of = [&](const char* key, std::size_t size) {
      const auto entry = hand.find(key);
      if (entry == hand.end() || !entry->is_array() || entry->size() != size ||
          !std::all_of(entry->begin(), entry->end(), [](const Json& v) { return v.is_number(); }))
        throw Error(path + ": hand " + std::to_string(i) + ": \"" + key + "\" is not " +
                    std::to_string(size) + " numbers");
    };
    vector_of("position_m", 3);
    vector_of("quaternion_xyzw", 4);
    Json kept = Json::object();
    for (const char* key : {"position_m", "quaternion_xyzw", "approach", "width_m", "open_width_m",
                            "score", "rank", "object", "label", "rejection"})
      if (hand.contains(key)) kept[key] = hand[key];
    out.push_back(std::move(kept));
  }
  return out;
}

}  // namespace

Json view_data(const ViewOptions& options) {
  std::string cloud_path, grasps_path;
  for (const std::string& input : options.inputs) {
    const std::string extension = extension_of(input);
    std::string& slot = extension == ".json" ? grasps_path : cloud_path;
    if (extension != ".json" && extension != ".pcd" && extension != ".ply")
      throw Error("view: '" + input +
                  "': not a cloud (.pcd, .ply) or a grasps file (.json from `antipode detect "
                  "--out`)");
    if (!slot.empty()) {
      std::string message = "view: '" + input + "': a second ";
      message.append(extension == ".json" ? "grasps file" : "cloud").append(" (after '");
      throw Error(message.append(slot).append("'); give one cloud and at most one grasps file"));
    }
    slot = input;
  }
  if (cloud_path.empty()) throw Error("view: give a cloud (.pcd or .ply) to show");
  Json data = {{"title", fs::path(cloud_path).filename().string()}, {"frame", "sensor"}};
  data["cloud"] = cloud_json(cloud_path);
  data["gripper"] = gripper_json(
      options.gripper_path.empty() ? "robots/grippers/baxter_electric.yaml" : options.gripper_path);
  data["hands"] = Json::array();
  if (!grasps_path.empty()) {
    const Json grasps = evaluation::read_json_file(grasps_path, "a grasps file");
    data["hands"] = hands_json(grasps, grasps_path);
    if (grasps.contains("frame") && grasps["frame"].is_string()) data["frame"] = grasps["frame"];
    data["title"] =
        data["title"].get<std::string>() + " + " + fs::path(grasps_path).filename().string();
  }
  return data;
}

std::string viewer_template_path() {
  const std::string shipped = shipped_data_dir();
  const fs::path installed = fs::path(shipped) / "viewer" / "antipode-view.html";
  if (!shipped.empty() && fs::is_regular_file(installed)) return installed.string();
  std::string built = ANTIPODE_VIEWER_PAGE;
  if (!built.empty() && fs::is_regular_file(built)) return built;
  if (built.empty())
    throw Error(
        "view: this antipode was built without its viewer: Node.js and npm were not "
        "found when it was configured (install them - scripts/packages.txt - and "
        "configure again)");
  throw Error("view: the viewer page '" + built + "' is missing: build the target antipode_viewer");
}

std::string view_page(const std::string& template_html, const Json& data) {
  const std::size_t mark = template_html.find(kDataMark);
  if (mark == std::string::npos)
    throw Error(std::string("view: the viewer page has no ") + kDataMark + " mark");
  // "</" never appears inside the script element: JSON may escape it as "<\/".
  std::string text = data.dump();
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3))
    text.replace(at, 2, "<\\/");
  return template_html.substr(0, mark) + "<script id=\"antipode-data\" type=\"application/json\">" +
         text + "</script>" + template_html.substr(mark + std::string(kDataMark).size());
}

}  // namespace antipode::cli
