#include <map>

#include "checks.hpp"

namespace antipode::bt::detail {
namespace {

// One port naming an entry of one tree.
struct Use {
  std::string tree;
  std::string key;
  std::type_index type;
  std::string type_name;
  std::string who;  // "port 'x' of Node"
  SourceLocation where;
};

// Entries connected by SubTree remapping form one class (union-find); a class has one type.
class EntryClasses {
 public:
  void unite(const std::string& tree_a, const std::string& key_a, const std::string& tree_b,
             const std::string& key_b) {
    parent_[root(id(tree_a, key_a))] = root(id(tree_b, key_b));
  }

  void add(Use use) { uses_.push_back(std::move(use)); }

  // Gives each class the type of its first use; throws at the first disagreeing use.
  void assign_types() {
    for (const Use& use : uses_) {
      const std::string cls = root(id(use.tree, use.key));
      const auto found = typed_.find(cls);
      if (found == typed_.end()) {
        typed_.emplace(cls, &use);
      } else if (found->second->type != use.type) {
        conflict(use, *found->second);
      }
    }
  }

  // The first use of the class of (tree, key), or null when no typed port names it.
  const Use* typed(const std::string& tree, const std::string& key) {
    const auto found = typed_.find(root(id(tree, key)));
    return found == typed_.end() ? nullptr : found->second;
  }

 private:
  static std::string id(const std::string& tree, const std::string& key) {
    return tree + '\x1f' + key;
  }

  std::string root(const std::string& node) {
    const auto found = parent_.find(node);
    if (found == parent_.end() || found->second == node) return node;
    const std::string top = root(found->second);
    parent_[node] = top;
    return top;
  }

  [[noreturn]] static void conflict(const Use& use, const Use& first) {
    const std::string other = first.key == use.key ? "it" : "{" + first.key + "}";
    throw Error(use.who + " uses {" + use.key + "} as " + use.type_name + ", but " + first.who +
                    " at " + first.where.str() + " uses " + other + " as " + first.type_name,
                use.where);
  }

  std::map<std::string, std::string> parent_;
  std::vector<Use> uses_;
  std::map<std::string, const Use*> typed_;
};

bool is_typed(std::type_index type) {
  return type != std::type_index(typeid(std::any)) && type != std::type_index(typeid(TextTemplate));
}

void collect(const NodeSpec& node, const std::string& tree, EntryClasses& classes) {
  for (const auto& [name, bound] : node.ports) {
    if (bound.source != PortBinding::Source::kEntry || !is_typed(bound.info.type)) continue;
    classes.add({tree, bound.key, bound.info.type, bound.info.type_name,
                 "port '" + name + "' of " + node.type, bound.where});
  }
  for (const auto& remap : node.remaps) {
    if (remap.parent_key) classes.unite(tree, *remap.parent_key, node.subtree, remap.port);
  }
  for (const auto& child : node.children) collect(child, tree, classes);
}

std::string used_as(const Use& use) {
  return "used as " + use.type_name + " by " + use.who + " at " + use.where.str();
}

void convert_remap(RemapSpec& remap, const std::string& subtree, EntryClasses& classes,
                   const LiteralConverters& converters) {
  const Use* use = classes.typed(subtree, remap.port);
  const std::string port = "port '" + remap.port + "' of tree '" + subtree + "'";
  if (use == nullptr) {
    const auto type = remap.literal.IsSequence() ? std::type_index(typeid(std::vector<std::string>))
                                                 : std::type_index(typeid(std::string));
    auto value = converters.parse(type, remap.literal);
    if (!value) throw Error(port + " expects text or a list of text", remap.where);
    remap.value = std::move(*value);
    return;
  }
  if (!converters.can_parse(use->type)) {
    throw Error(port + " is " + used_as(*use) + ", which cannot be written as a literal; " +
                    "write \"{entry}\"",
                remap.where);
  }
  auto value = converters.parse(use->type, remap.literal);
  if (!value) {
    const std::string got = remap.literal.IsScalar() ? "'" + remap.literal.Scalar() + "'"
                                                     : describe_yaml(remap.literal);
    throw Error(port + " is " + used_as(*use) + ", but got " + got, remap.where);
  }
  remap.value = std::move(*value);
}

void convert_remaps(NodeSpec& node, EntryClasses& classes, const LiteralConverters& converters) {
  for (auto& remap : node.remaps) {
    if (!remap.parent_key) convert_remap(remap, node.subtree, classes, converters);
  }
  for (auto& child : node.children) convert_remaps(child, classes, converters);
}

void check_override(const std::string& tree, const std::string& key, const std::string& text,
                    EntryClasses& classes, const LiteralConverters& converters) {
  const Use* use = classes.typed(tree, key);
  if (use == nullptr || use->type == std::type_index(typeid(std::string))) return;
  const std::string what = "--set " + key + "=" + text + ": {" + key + "} is " + used_as(*use);
  if (!converters.can_parse(use->type)) throw Error(what + ", which cannot be set from text");
  if (!converters.parse_text(use->type, text)) {
    throw Error(what + ", and '" + text + "' is not a valid " + use->type_name);
  }
}

}  // namespace

void check_entry_types(FileSpec& spec, const LiteralConverters& converters,
                       const std::vector<std::pair<std::string, std::string>>& entry_overrides) {
  EntryClasses classes;
  for (const auto& tree : spec.trees) collect(tree.root, tree.name, classes);
  classes.assign_types();
  for (auto& tree : spec.trees) convert_remaps(tree.root, classes, converters);
  for (const auto& [key, text] : entry_overrides) {
    check_override(spec.main, key, text, classes, converters);
  }
}

}  // namespace antipode::bt::detail
