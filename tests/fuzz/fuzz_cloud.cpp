// PCD and PLY clouds: the first byte chooses the format, the rest is the file.
#include "antipode/core/error.hpp"
#include "antipode/io/load_cloud.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const antipode::fuzz::InputFile file(data + 1, size - 1, data[0] % 2 ? "ply" : "pcd");
  try {
    antipode::load_cloud(file.path());
  } catch (const antipode::Error&) {
  }
  return 0;
}
