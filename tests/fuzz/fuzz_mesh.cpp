// OBJ meshes (the object folders' visual.obj and the blob sets' NNN.obj).
#include "antipode/core/error.hpp"
#include "fuzz_input.hpp"
#include "mesh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const antipode::fuzz::InputFile file(data, size, "obj");
  try {
    antipode::cells::read_obj(file.path());
  } catch (const antipode::Error&) {
  }
  return 0;
}
