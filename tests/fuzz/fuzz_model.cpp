// Classifier model files.
#include "antipode/core/error.hpp"
#include "antipode/grasp/svm_model.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const antipode::fuzz::InputFile file(data, size, "model");
  try {
    antipode::SvmModel::load(file.path());
  } catch (const antipode::Error&) {
  }
  return 0;
}
