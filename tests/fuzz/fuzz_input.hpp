#pragma once
// Fuzz targets: the input as a file, since the loaders read paths. Each target's entry point
// is LLVMFuzzerTestOneInput (libFuzzer's); an input may make the loader throw
// antipode::Error (a clear error is the promised behaviour), anything else - a crash,
// another exception, a hang - is a finding.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

namespace antipode::fuzz {

/// A file holding `size` bytes of `data`, named with `extension` ("pcd", ...), removed when
/// the object goes.
class InputFile {
 public:
  InputFile(const std::uint8_t* data, std::size_t size, const std::string& extension)
      : path_("/tmp/antipode-fuzz-" + std::to_string(::getpid()) + "." + extension) {
    std::ofstream(path_, std::ios::binary).write(reinterpret_cast<const char*>(data),
                                                 static_cast<std::streamsize>(size));
  }
  ~InputFile() { std::remove(path_.c_str()); }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace antipode::fuzz
