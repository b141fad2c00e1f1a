// --set values: each line of the input is one "key=value" override, applied to a fixed tree
// with one component.
#include <sstream>
#include <string>

#include "antipode/bt/loader.hpp"
#include "antipode/core/error.hpp"
#include "fake_components.hpp"

namespace {

const char* const kTree = R"(
components:
  sampler: { plugin: fake, samples: 3, box: { min: [0, 0, 0] } }
main: t
trees:
  t:
    Sequence:
      - SetBlackboard: { key: a, value: "{entry}" }
)";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const antipode::fuzz::FakeSource source;
  antipode::bt::LoadOptions options;
  options.components = &source;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string line; std::getline(lines, line) && options.overrides.size() < 16;) {
    const auto equals = line.find('=');
    if (equals == std::string::npos) continue;
    options.overrides.emplace_back(line.substr(0, equals), line.substr(equals + 1));
  }
  try {
    antipode::bt::load_tree_string(kTree, "fuzz.yaml", options);
  } catch (const antipode::Error&) {
  }
  return 0;
}
