// Scene files of the simulated cell (parsed, not built: building runs the physics).
#include "antipode/core/error.hpp"
#include "fuzz_input.hpp"
#include "scene_spec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const antipode::fuzz::InputFile file(data, size, "yaml");
  try {
    antipode::cells::read_scene(file.path());
  } catch (const antipode::Error&) {
  }
  return 0;
}
