#pragma once
/// @file
/// The index of a plugin directory: what each library in it provides, so that a host can
/// open only the libraries a tree needs (PluginHost::load_for) instead of every one.
///
/// Contract:
/// - The index is the file `antipode_plugins.index` in the plugin directory. It lists every
///   plugin file of the directory (`libantipode_*.so`) with its size and modification time,
///   and the types each library provides when the host loads it. Write it with
///   `antipode plugins --write-index DIR` (the build and `cmake --install` do).
/// - An index is *current* when it was written by a host of this plugin ABI and lists
///   exactly the directory's plugin files with their present sizes and modification times;
///   a rebuilt, added or removed library makes it stale, and a stale or missing index is
///   never trusted (the host then loads the directory whole).
/// - Format (text, one record per line, fields separated by single spaces):
///     antipode-plugin-index 1 abi MAJOR.MINOR     (the plugin ABI of the host that wrote it)
///     lib FILE SIZE MTIME_NS
///     type NAME            (zero or more, for the preceding lib)
/// - Reading and writing are single-threaded; write_plugin_index replaces the file
///   all-or-nothing (core/atomic_file.hpp).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace antipode {

/// The file name of a directory's index.
inline constexpr const char* kPluginIndexFile = "antipode_plugins.index";

struct PluginIndex {
  struct Library {
    std::string file;                ///< file name within the directory
    std::uintmax_t size_bytes = 0;   ///< when indexed
    std::int64_t mtime_ns = 0;       ///< last modification when indexed, ns since the epoch
    std::vector<std::string> types;  ///< what it provides when loaded (none when refused)
  };
  std::vector<Library> libraries;  ///< sorted by file name
};

/// Loads every plugin file of `directory` with a host of its own and writes the directory's
/// index. Returns how many libraries it lists. Throws antipode::Error when the index cannot
/// be written.
std::size_t write_plugin_index(const std::string& directory);

/// The index of `directory` when it is present, well formed and current (above); nullopt
/// otherwise. Never throws for a bad or stale index.
std::optional<PluginIndex> read_current_plugin_index(const std::string& directory);

}  // namespace antipode
