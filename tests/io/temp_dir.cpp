#include "temp_dir.hpp"

#include <fstream>
#include <random>
#include <sstream>

#include <unistd.h>

namespace antipode::testing {

TempDir::TempDir() {
  std::random_device device;
  // Memory-backed when available: the malformed-input tests write hundreds of small files.
  const std::filesystem::path shm("/dev/shm");
  const bool in_memory = std::filesystem::is_directory(shm) && ::access("/dev/shm", W_OK) == 0;
  path_ = (in_memory ? shm : std::filesystem::temp_directory_path()) /
          ("antipode_io_" + std::to_string(::getpid()) + "_" + std::to_string(device()));
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

std::string read_bytes(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace antipode::testing
