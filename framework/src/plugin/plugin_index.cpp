#include "antipode/plugin/plugin_index.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "antipode/core/atomic_file.hpp"
#include "antipode/core/error.hpp"
#include "antipode/plugin/abi.hpp"
#include "antipode/plugin/plugin_host.hpp"
#include "plugin_files.hpp"

namespace antipode {
namespace fs = std::filesystem;
namespace {

// The format, and the plugin ABI of the host that wrote it (which libraries it refused).
std::string header() {
  return "antipode-plugin-index 1 abi " + std::to_string(kAbiMajor) + "." +
         std::to_string(kAbiMinor);
}
constexpr std::uintmax_t kMaxIndexBytes = 1 << 20;

// Size and modification time of a plugin file, as the index records them.
PluginIndex::Library stamp(const fs::path& path) {
  PluginIndex::Library library;
  library.file = path.filename().string();
  library.size_bytes = fs::file_size(path);
  library.mtime_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                         fs::last_write_time(path).time_since_epoch())
                         .count();
  return library;
}

// Every plugin file of `directory` with its present stamp, sorted by name.
std::vector<PluginIndex::Library> stamps_in(const std::string& directory) {
  std::vector<PluginIndex::Library> stamps;
  for (const auto& path : detail::plugin_files_in(directory)) stamps.push_back(stamp(path));
  return stamps;
}

std::optional<PluginIndex> parse_index(std::istream& in) {
  std::string line;
  if (!std::getline(in, line) || line != header()) return std::nullopt;
  PluginIndex index;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string tag;
    fields >> tag;
    if (tag == "lib") {
      PluginIndex::Library library;
      if (!(fields >> library.file >> library.size_bytes >> library.mtime_ns)) return std::nullopt;
      index.libraries.push_back(std::move(library));
    } else if (tag == "type" && !index.libraries.empty()) {
      std::string type;
      if (!(fields >> type)) return std::nullopt;
      index.libraries.back().types.push_back(type);
    } else {
      return std::nullopt;
    }
  }
  return index;
}

}  // namespace

std::size_t write_plugin_index(const std::string& directory) {
  std::error_code error;
  if (!fs::is_directory(directory, error)) throw Error("no plugin directory " + directory);
  std::vector<PluginIndex::Library> libraries;
  try {
    libraries = stamps_in(directory);
  } catch (const fs::filesystem_error& e) {
    throw Error("cannot read plugin directory " + directory + ": " + e.code().message());
  }
  PluginHost host(std::vector<std::string>{});
  for (auto& library : libraries) {
    const PluginRecord& record = host.load_library((fs::path(directory) / library.file).string());
    for (const std::string& offer : record.offers) {
      library.types.push_back(offer.substr(offer.find(' ') + 1));  // "kind type"
    }
  }
  write_file_atomically((fs::path(directory) / kPluginIndexFile).string(),
                        [&](const std::string& temporary) {
                          std::ofstream out(temporary);
                          out << header() << "\n";
                          for (const auto& library : libraries) {
                            out << "lib " << library.file << " " << library.size_bytes << " "
                                << library.mtime_ns << "\n";
                            for (const auto& type : library.types) out << "type " << type << "\n";
                          }
                          if (!out.flush()) throw Error("cannot write " + temporary);
                        });
  return libraries.size();
}

std::optional<PluginIndex> read_current_plugin_index(const std::string& directory) {
  try {
    const fs::path file = fs::path(directory) / kPluginIndexFile;
    if (!fs::is_regular_file(file) || fs::file_size(file) > kMaxIndexBytes) return std::nullopt;
    std::ifstream in(file);
    std::optional<PluginIndex> index = parse_index(in);
    if (!index) return std::nullopt;
    const std::vector<PluginIndex::Library> present = stamps_in(directory);
    if (present.size() != index->libraries.size()) return std::nullopt;
    for (std::size_t i = 0; i < present.size(); ++i) {
      const auto& listed = index->libraries[i];
      if (listed.file != present[i].file || listed.size_bytes != present[i].size_bytes ||
          listed.mtime_ns != present[i].mtime_ns)
        return std::nullopt;
    }
    return index;
  } catch (const fs::filesystem_error&) {
    return std::nullopt;
  }
}

}  // namespace antipode
