#pragma once
/// @file
/// The plugin host: finds plugin libraries, loads them safely and creates what they offer.
///
/// Contract:
/// - A plugin library is a file named `libantipode_<name>.so` in a search directory. The
///   search path is the directories of `ANTIPODE_PLUGIN_PATH` (colon-separated, in order),
///   then this build tree's plugin directory, then `antipode/plugins` beside the
///   installed libantipode.so (`<prefix>/lib/antipode/plugins`). When two
///   directories hold a file of the same name, the earlier one wins.
/// - Libraries are opened with dlopen(RTLD_NOW | RTLD_LOCAL). A library is refused - recorded
///   with its path and reason, never thrown, never crashing - when dlopen fails (dlerror()
///   text, C++ names demangled), the entry symbol is missing, the ABI major differs or the minor is
///   newer than the host's (both versions named), the descriptor is malformed, or one of its
///   type names is already offered by a loaded library.
/// - A library stays loaded while the host or any component created from it lives.

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "antipode/plugin/abi.hpp"
#include "antipode/plugin/component_source.hpp"

namespace antipode {

/// What happened to one library file.
struct PluginRecord {
  enum class State { kLoaded, kRefused, kShadowed };
  std::string path;
  State state = State::kRefused;
  std::string reason;               ///< why refused or shadowed; empty when loaded
  std::string name;                 ///< from the descriptor, when it could be read
  std::string version;              ///< from the descriptor, when it could be read
  std::string abi;                  ///< "major.minor" it was built for, when it could be read
  std::vector<std::string> offers;  ///< "kind type" for each factory of a loaded library
};

const char* to_string(PluginRecord::State state);

class PluginHost : public ComponentSource {
 public:
  /// `ANTIPODE_PLUGIN_PATH` directories, then the build tree's `plugins/` (only for the build
  /// tree's own libantipode, not an installed copy), then `antipode/plugins` beside libantipode.
  static std::vector<std::string> default_search_path();

  explicit PluginHost(std::vector<std::string> search_path = default_search_path());
  ~PluginHost() override;
  PluginHost(const PluginHost&) = delete;
  PluginHost& operator=(const PluginHost&) = delete;

  /// Loads every plugin library found on the search path. Refusals are recorded.
  void load_search_path();

  /// Loads only the libraries that provide some of `names` (component types, node types;
  /// other names are ignored), as the directories' indexes tell (plugin_index.hpp), every
  /// library of a directory without a current index, and every library offering a type that
  /// is not a plain word (letters, digits, '_'); the first directory holding a file name
  /// wins, as in load_search_path. It loads the whole search path instead when two indexed
  /// libraries offer one type, or a directory without a current index follows an indexed
  /// one - the cases where loading only some could keep what a full load refuses. Call it
  /// once, on a host that has loaded nothing.
  void load_for(const std::vector<std::string>& names);

  /// Loads one library file; returns its record (loaded or refused).
  const PluginRecord& load_library(const std::string& path);

  /// Every library seen so far, in the order they were considered.
  const std::vector<PluginRecord>& records() const { return records_; }
  const std::vector<std::string>& search_path() const { return search_path_; }

  /// Registers the node types of every loaded library into `registry`. Throws
  /// antipode::Error when a plugin node type collides with one already in the registry.
  void register_nodes(bt::NodeRegistry& registry) const;

  /// The node types offered by loaded libraries.
  std::vector<std::string> node_types() const;

  // ComponentSource
  std::vector<std::string> component_types() const override;
  std::optional<ComponentKind> kind_of(const std::string& type) const override;
  std::shared_ptr<Component> create(const std::string& type,
                                    const Parameters& params) const override;
  bool check(const std::string& type, const Parameters& params) const override;

 private:
  struct Library;
  struct Offer {
    std::shared_ptr<Library> library;
    const PluginFactory* factory;
    void (*check)(const Parameters& params) = nullptr;  // the plugin's, if it has one
  };

  std::string refuse_reason(const PluginDescriptor& descriptor) const;
  /// The offer making components of `type`; throws the unknown-type error otherwise.
  const Offer& component_offer(const std::string& type, const Parameters& params) const;

  std::vector<std::string> search_path_;
  std::vector<PluginRecord> records_;
  std::map<std::string, Offer> offers_;  // type name -> factory
};

/// "libantipode_<name>.so" for a plugin name.
std::string plugin_file_name(const std::string& plugin_name);

/// Whether a plugin directory loads the file `path`: its name is "libantipode_<name>.so".
bool is_plugin_file_name(const std::string& path);

}  // namespace antipode
