#pragma once
// A scratch directory for one test, removed with everything in it at the end of the test.

#include <filesystem>
#include <string>

namespace antipode::testing {

class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  /// `name` inside the directory.
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

/// Writes `bytes` to `path` (binary), replacing it.
void write_bytes(const std::string& path, const std::string& bytes);
/// The content of `path`.
std::string read_bytes(const std::string& path);

}  // namespace antipode::testing
