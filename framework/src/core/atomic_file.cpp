#include "antipode/core/atomic_file.hpp"

#include <unistd.h>

#include <filesystem>

#include "antipode/core/error.hpp"

namespace antipode {
namespace fs = std::filesystem;

void write_file_atomically(const std::string& path,
                           const std::function<void(const std::string&)>& write) {
  const fs::path target(path);
  if (target.filename().empty()) throw Error("cannot write '" + path + "': not a file name");
  const fs::path directory = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(directory)) {
    throw Error("cannot write '" + path + "': directory '" + directory.string() +
                "' does not exist");
  }
  // Keep the extension last: some writers (OpenCV) choose the format from it.
  const fs::path temporary = directory / ("." + target.stem().string() + ".partial-" +
                                          std::to_string(::getpid()) + target.extension().string());
  try {
    write(temporary.string());
    if (!fs::exists(temporary)) throw Error("nothing was written");
    fs::rename(temporary, target);
  } catch (const std::exception& error) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw Error("cannot write '" + path + "': " + error.what());
  }
}

}  // namespace antipode
