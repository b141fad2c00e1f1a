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
  // The rename would replace whatever `path` names: only a regular file (or nothing) may be
  // replaced, never a device, a FIFO, a socket or a folder (`--out /dev/null` must not
  // destroy /dev/null).
  std::error_code error_code;
  const fs::file_status status = fs::status(target, error_code);
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw Error("cannot write '" + path + "': it exists and is not a regular file (" +
                (fs::is_directory(status) ? "a folder" : "a device, FIFO or socket") +
                "); give the path of a file");
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
