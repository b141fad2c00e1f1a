#include "antipode/evaluation/scratch_folder.hpp"

#include <cstdlib>

#include "antipode/core/error.hpp"

namespace antipode::evaluation {

ScratchFolder::ScratchFolder(const std::string& purpose) {
  std::string pattern =
      (std::filesystem::temp_directory_path() / ("antipode-" + purpose + "-XXXXXX")).string();
  if (mkdtemp(pattern.data()) == nullptr)
    throw Error("cannot make a temporary folder in " +
                std::filesystem::temp_directory_path().string());
  path_ = pattern;
}

ScratchFolder::~ScratchFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace antipode::evaluation
