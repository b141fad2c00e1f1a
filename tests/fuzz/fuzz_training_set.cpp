// Training-set files.
#include "antipode/core/error.hpp"
#include "antipode/grasp/training_set.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const antipode::fuzz::InputFile file(data, size, "data");
  try {
    antipode::load_training_set(file.path());
  } catch (const antipode::Error&) {
  }
  return 0;
}
