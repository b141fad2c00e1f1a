#pragma once
// A folder of one's own in the system's temporary folder, removed with everything in it when
// the object goes: for files a command makes on its way to its output (a report's charts, a
// scene's cloud for the viewer), so that a failed command leaves nothing behind.

#include <filesystem>
#include <string>

namespace antipode::evaluation {

class ScratchFolder {
 public:
  /// Makes TMP/antipode-PURPOSE-XXXXXX (mkdtemp: unique across processes and threads).
  /// Throws antipode::Error when it cannot be made.
  explicit ScratchFolder(const std::string& purpose);
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// `name` inside the folder.
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace antipode::evaluation
