// OBJ and binary STL meshes: the first byte chooses the format, the rest is the file.
#include "antipode/core/error.hpp"
#include "fuzz_input.hpp"
#include "mesh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool stl = data[0] % 2 != 0;
  const antipode::fuzz::InputFile file(data + 1, size - 1, stl ? "stl" : "obj");
  try {
    if (stl)
      antipode::cells::read_binary_stl(file.path());
    else
      antipode::cells::read_obj(file.path());
  } catch (const antipode::Error&) {
  }
  return 0;
}
