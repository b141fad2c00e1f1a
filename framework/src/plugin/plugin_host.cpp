#include "antipode/plugin/plugin_host.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cctype>

#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

#include "../core/library_dir.hpp"
#include "antipode/config.hpp"
#include "antipode/core/error.hpp"
#include "antipode/plugin/plugin_index.hpp"
#include "dl_error.hpp"
#include "elf_check.hpp"
#include "plugin_files.hpp"
#include "plugin_kind.hpp"

namespace antipode {
namespace fs = std::filesystem;

/// An open library; dlclose()d when the last owner (host or component) lets go. An accepted
/// library is marked RTLD_NODELETE (keep_mapped), so that dlclose() leaves its code mapped
/// until the process exits: threads outlive components - a TBB worker may still be returning
/// through a task the plugin instantiated, and a thread's exit runs TLS destructors of the
/// libraries the plugin pulled in (OpenCV's) - and must not jump into unmapped code.
struct PluginHost::Library {
  void* handle = nullptr;
  std::string path;
  const PluginDescriptor* descriptor = nullptr;
  ~Library() {
    if (handle != nullptr) dlclose(handle);
  }
};

namespace {

std::string version_text(std::uint32_t major, std::uint32_t minor) {
  return std::to_string(major) + "." + std::to_string(minor);
}

std::vector<std::string> split_path_list(const char* text) {
  std::vector<std::string> parts;
  if (text == nullptr) return parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, ':')) {
    if (!part.empty()) parts.push_back(part);
  }
  return parts;
}

// The descriptor fields the host reads end with `factories`, a pointer: its size is a pointer's.
constexpr std::size_t kDescriptorBytesRead =
    offsetof(PluginDescriptor, factories) +
    sizeof(PluginDescriptor::factories);  // NOLINT(bugprone-sizeof-expression): the field's size

// The parameter checks follow the factories (since ABI 10.1).
constexpr std::size_t kDescriptorBytesWithChecks =
    offsetof(PluginDescriptor, checks) +
    sizeof(PluginDescriptor::checks);  // NOLINT(bugprone-sizeof-expression): the field's size

// The parameter checks of a descriptor (none in one too short to hold them: a descriptor
// written without them, as a plugin compiled for ABI 10.0 wrote it).
std::pair<const PluginParameterCheck*, std::uint32_t> checks_of(const PluginDescriptor& d) {
  if (d.descriptor_size < kDescriptorBytesWithChecks) return {nullptr, 0};
  return {d.checks, d.check_count};
}

// Why a descriptor's parameter checks cannot be used, or "".
std::string checks_problem(const PluginDescriptor& d) {
  const auto [checks, count] = checks_of(d);
  if (count > 0 && checks == nullptr) return "parameter checks: a null table";
  for (std::uint32_t i = 0; i < count; ++i) {
    const PluginParameterCheck& c = checks[i];
    if (c.type == nullptr || c.check == nullptr)
      return "parameter check " + std::to_string(i) + ": a null type or function";
    bool offered = false;
    for (std::uint32_t f = 0; f < d.factory_count; ++f) {
      offered = offered ||
                (d.factories[f].create != nullptr && std::string(d.factories[f].type) == c.type);
    }
    if (!offered) {
      return "parameter check " + std::to_string(i) + ": '" + c.type +
             "' is no component type of this plugin";
    }
  }
  return "";
}

using detail::library_dir;

// <directory of libantipode.so>/antipode/plugins: found at run time, so an installed tree
// works from whatever prefix it was installed to.
std::string installed_plugin_dir() {
  return (library_dir() / ANTIPODE_PLUGIN_DIR_BESIDE_LIBRARY).lexically_normal().string();
}

// Whether this libantipode.so is the build tree's (not an installed copy, which must not pick
// up the plugins of the build it was made from).
bool running_from_build_tree() {
  const fs::path dir = library_dir();
  if (dir.empty()) return true;
  const fs::path build_root = fs::path(ANTIPODE_PLUGIN_BUILD_DIR).parent_path();
  std::error_code error;
  const fs::path relative = fs::relative(fs::weakly_canonical(dir, error),
                                         fs::weakly_canonical(build_root, error), error);
  return !error && !relative.empty() && *relative.begin() != "..";
}

// Promotes an open library to RTLD_NODELETE (see PluginHost::Library).
void keep_mapped(const std::string& path) {
  if (void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE)) dlclose(handle);
}

}  // namespace

const char* to_string(PluginRecord::State state) {
  switch (state) {
    case PluginRecord::State::kLoaded:
      return "loaded";
    case PluginRecord::State::kRefused:
      return "refused";
    case PluginRecord::State::kShadowed:
      return "shadowed";
  }
  return "?";
}

std::string plugin_file_name(const std::string& plugin_name) {
  return "libantipode_" + plugin_name + ".so";
}

std::vector<std::string> PluginHost::default_search_path() {
  std::vector<std::string> path = split_path_list(std::getenv("ANTIPODE_PLUGIN_PATH"));
  if (running_from_build_tree()) path.emplace_back(ANTIPODE_PLUGIN_BUILD_DIR);
  path.push_back(installed_plugin_dir());
  return path;
}

PluginHost::PluginHost(std::vector<std::string> search_path)
    : search_path_(std::move(search_path)) {}

PluginHost::~PluginHost() = default;

void PluginHost::load_search_path() {
  std::map<std::string, std::string> first_seen;  // file name -> path that won
  for (const auto& directory : search_path_) {
    for (const auto& file : detail::plugin_files_in(directory)) {
      const auto [winner, inserted] = first_seen.emplace(file.filename().string(), file.string());
      if (inserted) {
        load_library(file.string());
      } else {
        records_.push_back({file.string(),
                            PluginRecord::State::kShadowed,
                            "shadowed by " + winner->second,
                            "",
                            "",
                            "",
                            {}});
      }
    }
  }
}

namespace {

// A type name made only of letters, digits and '_': what a tree file's words can name. A
// library offering another is always opened.
bool is_word(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
  });
}

}  // namespace

void PluginHost::load_for(const std::vector<std::string>& names) {
  // The winning path of each file name (the first directory holding it, as in
  // load_search_path), in search order; what the indexed ones provide; and the libraries
  // of directories without a current index, which are all needed. An unindexed directory
  // after an indexed one could offer a type of a library that is not opened, which a full
  // load would refuse: then everything is loaded.
  std::map<std::string, std::string> winner;
  std::vector<std::string> order;
  std::map<std::string, std::string> provider;  // type -> path
  std::set<std::string> needed;
  bool indexed_before = false;
  for (const auto& directory : search_path_) {
    const std::vector<fs::path> files = detail::plugin_files_in(directory);
    if (files.empty()) continue;
    const std::optional<PluginIndex> index = read_current_plugin_index(directory);
    if (!index && indexed_before) return load_search_path();
    indexed_before = indexed_before || index.has_value();
    std::set<std::string> won;
    for (const auto& file : files) {
      if (!winner.emplace(file.filename().string(), file.string()).second) continue;
      won.insert(file.filename().string());
      order.push_back(file.string());
      if (!index) needed.insert(file.string());
    }
    if (!index) continue;
    for (const auto& library : index->libraries) {
      if (won.count(library.file) == 0) continue;
      const std::string path = (fs::path(directory) / library.file).string();
      for (const auto& type : library.types) {
        // Two libraries offering one type: loading everything reports it.
        if (!provider.emplace(type, path).second) return load_search_path();
        if (!is_word(type)) needed.insert(path);
      }
    }
  }
  for (const auto& name : names) {
    if (const auto it = provider.find(name); it != provider.end()) needed.insert(it->second);
  }
  for (const auto& path : order) {
    if (needed.count(path) != 0) load_library(path);
  }
}

std::string PluginHost::refuse_reason(const PluginDescriptor& descriptor) const {
  if (descriptor.abi_major != kAbiMajor || descriptor.abi_minor > kAbiMinor) {
    return "built for plugin ABI " + version_text(descriptor.abi_major, descriptor.abi_minor) +
           ", but this antipode provides ABI " + version_text(kAbiMajor, kAbiMinor) +
           " (rebuild the plugin against this antipode)";
  }
  if (descriptor.descriptor_size < kDescriptorBytesRead) {
    return "descriptor is " + std::to_string(descriptor.descriptor_size) +
           " bytes, expected at least " + std::to_string(kDescriptorBytesRead);
  }
  if (descriptor.name == nullptr || descriptor.version == nullptr ||
      (descriptor.factory_count > 0 && descriptor.factories == nullptr)) {
    return "descriptor has a null name, version or factory table";
  }
  std::set<std::string> own_types;
  for (std::uint32_t i = 0; i < descriptor.factory_count; ++i) {
    const PluginFactory& factory = descriptor.factories[i];
    const std::string problem = factory_problem(factory);
    if (!problem.empty()) return "factory " + std::to_string(i) + ": " + problem;
    const auto existing = offers_.find(factory.type);
    if (existing != offers_.end()) {
      return "type '" + std::string(factory.type) + "' is already provided by " +
             existing->second.library->path;
    }
    if (factory.register_node != nullptr && is_builtin_node(factory.type)) {
      return "node type '" + std::string(factory.type) + "' is a built-in node";
    }
    if (!own_types.insert(factory.type).second) {
      return "type '" + std::string(factory.type) + "' is offered twice";
    }
  }
  return checks_problem(descriptor);
}

const PluginRecord& PluginHost::load_library(const std::string& path) {
  PluginRecord record{path, PluginRecord::State::kRefused, "", "", "", "", {}};
  if (std::string problem = detail::elf_problem(path); !problem.empty()) {
    record.reason = std::move(problem);
    records_.push_back(std::move(record));
    return records_.back();
  }
  dlerror();  // clear any stale error
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* text = dlerror();
    record.reason = text != nullptr ? detail::readable_dl_error(text) : "dlopen failed";
    records_.push_back(std::move(record));
    return records_.back();
  }
  auto library = std::make_shared<Library>();
  library->handle = handle;
  library->path = path;
  void* symbol = dlsym(handle, "antipode_plugin_descriptor");
  if (symbol == nullptr) {
    record.reason =
        "no entry symbol 'antipode_plugin_descriptor' (did the plugin use "
        "ANTIPODE_PLUGIN(...)?)";
    records_.push_back(std::move(record));
    return records_.back();
  }
  const auto entry = reinterpret_cast<antipode_plugin_entry_fn>(symbol);
  const PluginDescriptor* descriptor = entry();
  if (descriptor != nullptr) {
    record.abi =
        std::to_string(descriptor->abi_major) + "." + std::to_string(descriptor->abi_minor);
  }
  record.reason =
      descriptor == nullptr ? "entry symbol returned no descriptor" : refuse_reason(*descriptor);
  if (!record.reason.empty()) {
    records_.push_back(std::move(record));
    return records_.back();
  }
  keep_mapped(path);
  library->descriptor = descriptor;
  record.state = PluginRecord::State::kLoaded;
  record.name = descriptor->name;
  record.version = descriptor->version;
  for (std::uint32_t i = 0; i < descriptor->factory_count; ++i) {
    const PluginFactory& factory = descriptor->factories[i];
    offers_[factory.type] = Offer{library, &factory};
    record.offers.push_back(std::string(factory.kind) + " " + factory.type);
  }
  const auto [checks, check_count] = checks_of(*descriptor);
  for (std::uint32_t i = 0; i < check_count; ++i) offers_[checks[i].type].check = checks[i].check;
  records_.push_back(std::move(record));
  return records_.back();
}

void PluginHost::register_nodes(bt::NodeRegistry& registry) const {
  for (const auto& [type, offer] : offers_) {
    if (offer.factory->register_node == nullptr) continue;
    register_plugin_node(registry, type, offer.library->path, offer.library,
                         offer.factory->register_node);
  }
}

std::vector<std::string> PluginHost::node_types() const {
  std::vector<std::string> types;
  for (const auto& [type, offer] : offers_) {
    if (offer.factory->register_node != nullptr) types.push_back(type);
  }
  return types;
}

std::vector<std::string> PluginHost::component_types() const {
  std::vector<std::string> types;
  for (const auto& [type, offer] : offers_) {
    if (offer.factory->create != nullptr) types.push_back(type);
  }
  return types;
}

std::optional<ComponentKind> PluginHost::kind_of(const std::string& type) const {
  const auto it = offers_.find(type);
  if (it == offers_.end()) return std::nullopt;
  return parse_component_kind(it->second.factory->kind);
}

const PluginHost::Offer& PluginHost::component_offer(const std::string& type,
                                                     const Parameters& params) const {
  const auto it = offers_.find(type);
  if (it == offers_.end() || it->second.factory->create == nullptr) {
    throw Error("unknown component type '" + type + "'" + did_you_mean(type, component_types()),
                params.location("plugin"), "run 'antipode plugins' to list what is available");
  }
  return it->second;
}

bool PluginHost::check(const std::string& type, const Parameters& params) const {
  const Offer& offer = component_offer(type, params);
  if (offer.check == nullptr) return false;
  try {
    offer.check(params);
  } catch (...) {
    rethrow_with_context(type, params.location("plugin"));
  }
  return true;
}

std::shared_ptr<Component> PluginHost::create(const std::string& type,
                                              const Parameters& params) const {
  const Offer& offer = component_offer(type, params);
  Component* raw = nullptr;
  try {
    raw = offer.factory->create(params);
  } catch (...) {
    rethrow_with_context(type, params.location("plugin"));
  }
  if (raw == nullptr) {
    throw Error("plugin " + offer.library->path + " returned no object for '" + type + "'");
  }
  // The deleter keeps the library loaded for as long as the component lives.
  std::shared_ptr<Component> component(
      raw, [library = offer.library](Component* object) { delete object; });
  const auto declared = parse_component_kind(offer.factory->kind);
  if (!declared || component->kind() != *declared) {
    throw Error("plugin " + offer.library->path + ": '" + type + "' is declared as a " +
                offer.factory->kind + " but creates a " + to_string(component->kind()));
  }
  return component;
}

}  // namespace antipode
