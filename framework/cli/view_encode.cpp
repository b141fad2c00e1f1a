#include "view_encode.hpp"

// libb64's C header declares its functions without C linkage for C++.
extern "C" {
#include <b64/cencode.h>
}

#include <algorithm>
#include <vector>

#include "antipode/core/error.hpp"

namespace antipode::cli {
using Json = nlohmann::ordered_json;

int name_index(const std::string& name, Json& names, std::map<std::string, int>& known) {
  const auto [at, added] = known.emplace(name, int(known.size()));
  if (added) names.push_back(name);
  return at->second;
}

// libb64, fed in chunks that its int lengths hold; it breaks lines every 72 characters, which
// are removed.
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

Json cloud_json(const Cloud& cloud) {
  std::vector<float> xyz;
  xyz.reserve(3 * cloud.points_m.size());
  for (const Eigen::Vector3f& p : cloud.points_m) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  Json out = {{"count", cloud.points_m.size()}, {"points", base64(xyz.data(), 4 * xyz.size())}};
  const auto& masks = cloud.view_masks;
  if (masks.size() == cloud.size() &&
      std::any_of(masks.begin(), masks.end(), [&](std::uint32_t m) { return m != masks.front(); }))
    out["views"] = base64(masks.data(), 4 * masks.size());
  return out;
}

Json hand_table(const Json& grasps, const std::string& path) {
  const auto hands = grasps.is_object() ? grasps.find("hands") : grasps.end();
  if (!grasps.is_object() || hands == grasps.end() || !hands->is_array())
    throw Error(path +
                ": not a grasps file (no \"hands\" list; `antipode detect --out` and "
                "WriteGrasps write one)");
  std::vector<float> position, quaternion, width, open_width, score;
  Json rank = Json::array(), object = Json::array(), label = Json::array(),
       rejection = Json::array(), labels = Json::array(), reasons = Json::array();
  std::map<std::string, int> label_index, reason_index;
  for (std::size_t i = 0; i < hands->size(); ++i) {
    const Json& hand = (*hands)[i];
    const auto numbers = [&](const char* key, std::size_t size, std::vector<float>& out) {
      const auto entry = hand.is_object() ? hand.find(key) : hand.end();
      if (!hand.is_object() || entry == hand.end() || !entry->is_array() || entry->size() != size ||
          !std::all_of(entry->begin(), entry->end(), [](const Json& v) { return v.is_number(); }))
        throw Error(path + ": hand " + std::to_string(i) + ": \"" + key + "\" is not " +
                    std::to_string(size) + " numbers");
      for (const Json& v : *entry) out.push_back(v.get<float>());
    };
    const auto number = [&](const char* key, float otherwise) {
      const auto entry = hand.find(key);
      return entry != hand.end() && entry->is_number() ? entry->get<float>() : otherwise;
    };
    const auto text = [&](const char* key) {
      const auto entry = hand.find(key);
      return entry != hand.end() && entry->is_string() ? entry->get<std::string>() : std::string();
    };
    numbers("position_m", 3, position);
    numbers("quaternion_xyzw", 4, quaternion);
    width.push_back(number("width_m", 0.0f));
    open_width.push_back(number("open_width_m", width.back()));
    score.push_back(number("score", 0.0f));
    rank.push_back(int(number("rank", 0.0f)));
    object.push_back(int(number("object", -1.0f)));
    const std::string l = text("label"), r = text("rejection");
    label.push_back(l.empty() ? -1 : name_index(l, labels, label_index));
    rejection.push_back(r.empty() ? -1 : name_index(r, reasons, reason_index));
  }
  const auto floats = [](const std::vector<float>& v) { return base64(v.data(), 4 * v.size()); };
  return {{"count", hands->size()},
          {"position_m", floats(position)},
          {"quaternion_xyzw", floats(quaternion)},
          {"width_m", floats(width)},
          {"open_width_m", floats(open_width)},
          {"score", floats(score)},
          {"rank", rank},
          {"object", object},
          {"label", label},
          {"labels", labels},
          {"rejection", rejection},
          {"reasons", reasons}};
}

}  // namespace antipode::cli
