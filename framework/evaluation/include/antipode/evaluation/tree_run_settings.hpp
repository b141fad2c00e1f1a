#pragma once
// What every command and bench that runs a tree takes from the user: --set overrides, the
// seed and the console trace, and the checks on those overrides.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace antipode::evaluation {

/// What every command that runs a tree takes from --set, --seed and -v (or run's -q); the
/// `antipode` command declares these options once, for all of them.
struct TreeRunSettings {
  std::vector<std::string> set;  ///< "key=value" overrides, applied after the command's own
  std::uint64_t seed = 0;        ///< seed of every random stream
  bool verbose = false;          ///< per-node console trace
  std::string main_tree;         ///< the tree to run instead of the file's `main` ("": main)
};

/// Splits "key=value" overrides; throws Error for an entry without '='.
std::vector<std::pair<std::string, std::string>> parse_overrides(
    const std::vector<std::string>& entries);

/// Throws Error for a user's `--set key=value` (a blackboard entry: no dot in `key`) that the
/// tree file at `tree_path` never reads as `{key}` - usually a component parameter given
/// without its component (`--set samples=10` for `--set sampler.samples=10`), which would
/// otherwise change nothing. The message suggests the components whose parameters in the file
/// have that name.
void check_entries_are_read(const std::string& tree_path, const std::vector<std::string>& set);

/// The value of the tree's setting `key` as a run sees it: the last `--set key=VALUE` of
/// `set`, else the tree file's `settings` entry (docs/trees.md, settings), as written; "" when
/// neither gives one (or the file cannot be read: loading the tree reports that).
std::string tree_setting(const std::string& tree_path, const std::vector<std::string>& set,
                         const std::string& key);

/// The robot file a pick tree runs with: the last `--set robot=FILE` of `set`, else the
/// tree file's `robot` setting (docs/trees.md, settings), resolved as the tree resolves it;
/// "" when it names none.
std::string tree_robot_path(const std::string& tree_path, const std::vector<std::string>& set);

}  // namespace antipode::evaluation
