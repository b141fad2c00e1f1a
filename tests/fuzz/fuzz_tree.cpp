// Tree files: loaded (parsed, validated, built) with the built-in nodes and one fake
// component type.
#include <string>

#include "antipode/bt/loader.hpp"
#include "antipode/core/error.hpp"
#include "fake_components.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const antipode::fuzz::FakeSource source;
  antipode::bt::LoadOptions options;
  options.components = &source;
  const std::string yaml(reinterpret_cast<const char*>(data), size);
  try {
    antipode::bt::load_tree_string(yaml, "fuzz.yaml", options);
  } catch (const antipode::Error&) {
  }
  return 0;
}
