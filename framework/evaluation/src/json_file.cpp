#include "antipode/evaluation/json_file.hpp"

#include <fstream>

#include "antipode/core/error.hpp"
#include "antipode/core/input_file.hpp"

namespace antipode::evaluation {
namespace {

using Json = nlohmann::ordered_json;

// Thrown by the parser's callback as soon as a value opens past kMaxJsonDepth.
struct TooDeep {};

}  // namespace

Json read_json_file(const std::string& path, const std::string& what) {
  require_regular_file(path, what);
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot read " + what);
  const Json::parser_callback_t bounded = [](int depth, Json::parse_event_t event, Json&) {
    const bool opens =
        event == Json::parse_event_t::object_start || event == Json::parse_event_t::array_start;
    if (opens && depth >= kMaxJsonDepth) throw TooDeep{};
    return true;
  };
  try {
    return Json::parse(in, bounded);
  } catch (const TooDeep&) {
    throw Error(path + ": nested deeper than " + std::to_string(kMaxJsonDepth) + " levels: not " +
                what);
  } catch (const Json::exception& e) {
    throw Error(path + ": not JSON (" + std::string(e.what()) + ")");
  }
}

}  // namespace antipode::evaluation
