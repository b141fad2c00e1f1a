#include "antipode/core/input_file.hpp"

#include <filesystem>

#include "antipode/core/error.hpp"

namespace antipode {

void require_regular_file(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status) || fs::is_regular_file(status)) return;
  throw Error(std::string("not a regular file (") +
                  (fs::is_directory(status) ? "a folder" : "a device or FIFO") + "): give " + what,
              {path});
}

}  // namespace antipode
