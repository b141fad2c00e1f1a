#pragma once
/// @file
/// The blackboard: typed entries shared by the nodes of one tree.
///
/// Each entry holds one value (std::any) whose type is fixed by its first write; writing or
/// reading it as another type throws antipode::Error. Text is the exception: an entry
/// holding a std::string (a `--set key=value`, a SetBlackboard literal) may be read as any
/// type the converter table parses and is replaced by the first value of another type
/// written to it, and text written into an entry of another parseable type is converted to
/// that type.
///
/// Every tree instance (the main tree, each SubTree node) has its own blackboard. A subtree's
/// blackboard sees its parent's entries only through explicit remapping: remap(key, parent,
/// parent_key) makes reads and writes of `key` act on the parent's `parent_key`.
///
/// Values are moved in, and large values should be passed as std::shared_ptr<const T> or read
/// with get_ref(). Not thread-safe: a tree ticks in one thread.

#include <any>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <typeindex>
#include <utility>
#include <vector>

#include "antipode/bt/converters.hpp"

namespace antipode::bt {

class Blackboard {
 public:
  /// `converters` parses text entries read as other types (null: the built-in table).
  explicit Blackboard(std::shared_ptr<const LiteralConverters> converters = nullptr);

  /// Stores `value` at `key` (moved, not copied).
  template <typename T>
  void set(const std::string& key, T value) {
    if constexpr (std::is_same_v<T, std::any>) {
      set_any(key, std::move(value));
    } else {
      set_any(key, std::any(std::move(value)));
    }
  }

  /// A copy of the value at `key` as T; throws Error when the entry is unset or of another
  /// type (text entries are converted when T is parseable).
  template <typename T>
  T get(const std::string& key) const {
    return std::any_cast<T>(get_as(key, std::type_index(typeid(T))));
  }

  /// The value at `key`, which must be of exactly type T; valid until the entry is written
  /// again. Throws Error when unset or of another type.
  template <typename T>
  const T& get_ref(const std::string& key) const {
    return std::any_cast<const T&>(require(key, std::type_index(typeid(T))));
  }

  /// Type-erased write; the rules of set<T>() apply with T = value.type().
  void set_any(const std::string& key, std::any value);

  /// The stored value, or null when `key` has never been written.
  const std::any* find(const std::string& key) const;

  /// A copy of the value at `key` converted to `type` (see get<T>()).
  std::any get_as(const std::string& key, std::type_index type) const;

  /// True once `key` has been written.
  bool has(const std::string& key) const { return find(key) != nullptr; }

  /// The type of the value at `key`, or nullopt when unset.
  std::optional<std::type_index> type_of(const std::string& key) const;

  /// The value at `key` printed for logs ("<unset>" when unset).
  std::string text(const std::string& key) const;

  /// Keys of entries written here, plus remapped keys whose target is set; sorted.
  std::vector<std::string> keys() const;

  /// From now on `key` here means `target_key` on `target`.
  void remap(const std::string& key, std::shared_ptr<Blackboard> target, std::string target_key);

  const LiteralConverters& converters() const { return *converters_; }
  std::shared_ptr<const LiteralConverters> shared_converters() const { return converters_; }

 private:
  struct Remap {
    std::shared_ptr<Blackboard> target;
    std::string key;
  };
  // The blackboard and key that `key` finally refers to, following remaps.
  std::pair<const Blackboard*, std::string> resolve(const std::string& key) const;
  std::pair<Blackboard*, std::string> resolve(const std::string& key);
  const std::any& require(const std::string& key, std::type_index type) const;

  std::shared_ptr<const LiteralConverters> converters_;
  std::map<std::string, std::any> entries_;
  std::map<std::string, Remap> remaps_;
};

}  // namespace antipode::bt

namespace antipode::bt {

/// True for a valid entry name: a letter or '_' followed by letters, digits or '_'.
bool is_valid_key(const std::string& key);

/// The key of a whole-value reference "{key}" (braces around a valid key), else nullopt.
std::optional<std::string> parse_reference(const std::string& text);

}  // namespace antipode::bt
