#include "antipode/evaluation/session.hpp"

#include <unistd.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

#include "antipode/bt/loader.hpp"
#include "antipode/core/error.hpp"
#include "antipode/evaluation/tree_run_settings.hpp"

namespace antipode::evaluation {
namespace {

// Tree files larger than this are not searched for names (every plugin is loaded instead).
constexpr std::uintmax_t kMaxScannedBytes = 16u << 20;

void add_words(const std::string& text, std::set<std::string>& words) {
  std::string word;
  for (const char c : text) {
    if (std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_') {
      word += c;
    } else if (!word.empty()) {
      words.insert(word), word.clear();
    }
  }
  if (!word.empty()) words.insert(word);
}

// Every word of the tree file and of `texts`: each name a tree uses - a node type, a
// component's `plugin` - is one of them; a word that is not such a name opens nothing, and
// one that names a type the tree does not use opens a library too many, nothing worse. A
// file that cannot be read gives the single name "*", which no library offers: loading the
// tree then fails and is retried with every plugin (load_tree_for), so the error is the
// loader's own.
std::vector<std::string> names_in(const std::string& tree_path,
                                  const std::vector<std::string>& texts) {
  std::set<std::string> words;
  for (const auto& text : texts) add_words(text, words);
  std::error_code error;
  const auto size = std::filesystem::file_size(tree_path, error);
  std::ifstream in(tree_path);
  if (error || size > kMaxScannedBytes || !std::filesystem::is_regular_file(tree_path, error) ||
      !in)
    return {"*"};
  std::stringstream content;
  content << in.rdbuf();
  add_words(content.str(), words);
  return {words.begin(), words.end()};
}

}  // namespace

Session open_session() {
  Session session{std::make_unique<PluginHost>(), bt::builtin_node_registry()};
  session.host->load_search_path();
  session.host->register_nodes(session.registry);
  return session;
}

void replace_with_full_session(Session& session) {
  Session full = open_session();
  Session old = std::move(session);
  session = std::move(full);
}

Session open_session_for(const std::string& tree_path, const std::vector<std::string>& entries,
                         const TreeRunSettings& settings) {
  const char* mode = std::getenv("ANTIPODE_PLUGIN_LOAD");
  if (mode != nullptr && std::string(mode) == "all") return open_session();
  std::vector<std::string> texts = entries;
  texts.insert(texts.end(), settings.set.begin(), settings.set.end());
  Session session{std::make_unique<PluginHost>(), bt::builtin_node_registry(), false};
  session.host->load_for(names_in(tree_path, texts));
  session.host->register_nodes(session.registry);
  return session;
}

Tracing attach_tracers(bt::Tree& tree, bool console, const std::string& trace_path) {
  Tracing tracing;
  if (console) {
    const bool colour = isatty(STDOUT_FILENO) != 0 && std::getenv("NO_COLOR") == nullptr;
    tracing.console = std::make_unique<bt::ConsoleTracer>(std::cout, colour);
    tree.add_observer(tracing.console.get());
  }
  if (!trace_path.empty()) {
    tracing.file = std::make_unique<bt::JsonlTracer>(trace_path);
    tree.add_observer(tracing.file.get());
  }
  tracing.witness = std::make_unique<bt::FailureWitness>();
  tree.add_observer(tracing.witness.get());
  return tracing;
}

std::string result_line(const std::string& tree_path, bt::Status status, const Tracing& tracing) {
  std::string line = tree_path + ": " + bt::to_string(status);
  const std::string& cause = tracing.witness ? tracing.witness->last_failure() : std::string();
  if (status == bt::Status::kFailure && !tracing.console && !cause.empty())
    line += " (" + cause + ")";
  return line;
}

void throw_with_refused_plugins_note(const UnknownTypeError& error, const PluginHost& host) {
  int refused = 0;
  for (const auto& record : host.records()) {
    if (record.state == PluginRecord::State::kRefused) ++refused;
  }
  if (refused == 0) throw error;
  throw UnknownTypeError(error.what() + std::string(" - note: ") + std::to_string(refused) +
                         " plugin " + (refused == 1 ? "library was" : "libraries were") +
                         " refused, and may provide it; see 'antipode plugins'");
}

bt::LoadOptions load_options(const Session& session, const std::vector<std::string>& entries,
                             const TreeRunSettings& settings) {
  std::vector<std::string> overrides = entries;
  overrides.insert(overrides.end(), settings.set.begin(), settings.set.end());
  bt::LoadOptions load;
  load.registry = &session.registry;
  load.components = session.host.get();
  load.seed = settings.seed;
  load.overrides = parse_overrides(overrides);
  load.main_tree = settings.main_tree;
  return load;
}

bt::Tree load_tree_for(Session& session, const std::string& tree_path,
                       const std::vector<std::string>& entries, const TreeRunSettings& settings) {
  check_entries_are_read(tree_path, settings.set);
  if (!session.every_plugin) {
    // Checked first (which builds no component): a tree the opened plugins cannot load is
    // loaded with all of them, so its errors are those of a full session. The parameters are
    // left to the load, which makes the components (a model is then read once).
    try {
      bt::LoadOptions names_only = load_options(session, entries, settings);
      names_only.check_component_parameters = false;
      bt::validate_tree_file(tree_path, names_only);
    } catch (const Error&) {
      replace_with_full_session(session);
    }
  }
  try {
    return bt::load_tree_file(tree_path, load_options(session, entries, settings));
  } catch (const UnknownTypeError& error) {
    throw_with_refused_plugins_note(error, *session.host);
  }
}

}  // namespace antipode::evaluation
