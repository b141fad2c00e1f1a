#include "antipode/bt/blackboard.hpp"

#include <algorithm>
#include <cctype>

#include "antipode/core/error.hpp"

namespace antipode::bt {
namespace {

const std::type_index kStringType(typeid(std::string));

std::string entry(const std::string& key) { return "blackboard entry {" + key + "}"; }

}  // namespace

Blackboard::Blackboard(std::shared_ptr<const LiteralConverters> converters)
    : converters_(converters ? std::move(converters)
                             : std::make_shared<const LiteralConverters>()) {}

std::pair<const Blackboard*, std::string> Blackboard::resolve(const std::string& key) const {
  const Blackboard* board = this;
  std::string name = key;
  for (auto remap = board->remaps_.find(name); remap != board->remaps_.end();
       remap = board->remaps_.find(name)) {
    board = remap->second.target.get();
    name = remap->second.key;
  }
  return {board, name};
}

std::pair<Blackboard*, std::string> Blackboard::resolve(const std::string& key) {
  const auto [board, name] = std::as_const(*this).resolve(key);
  return {const_cast<Blackboard*>(board), name};
}

void Blackboard::set_any(const std::string& key, std::any value) {
  auto [board, name] = resolve(key);
  const auto found = board->entries_.find(name);
  if (found == board->entries_.end()) {
    board->entries_.emplace(name, std::move(value));
    return;
  }
  const std::type_index held(found->second.type());
  const std::type_index incoming(value.type());
  if (held == incoming) {
    found->second = std::move(value);
    return;
  }
  if (incoming == kStringType && converters_->can_parse(held)) {
    const auto& text = std::any_cast<const std::string&>(value);
    auto converted = converters_->parse_text(held, text);
    if (!converted) {
      throw Error(entry(key) + " holds " + type_name(held) + ", and the text '" + text +
                  "' is not a valid " + type_name(held));
    }
    found->second = std::move(*converted);
    return;
  }
  if (held == kStringType) {  // a text entry takes the type of the first typed write
    found->second = std::move(value);
    return;
  }
  throw Error(entry(key) + " holds " + type_name(held) + "; cannot store " + type_name(incoming) +
              " in it");
}

const std::any* Blackboard::find(const std::string& key) const {
  const auto [board, name] = resolve(key);
  const auto found = board->entries_.find(name);
  return found == board->entries_.end() ? nullptr : &found->second;
}

const std::any& Blackboard::require(const std::string& key, std::type_index type) const {
  const std::any* value = find(key);
  if (value == nullptr) throw Error(entry(key) + " has not been written");
  if (std::type_index(value->type()) != type) {
    throw Error(entry(key) + " holds " + type_name(value->type()) + ", not " + type_name(type));
  }
  return *value;
}

std::any Blackboard::get_as(const std::string& key, std::type_index type) const {
  const std::any* value = find(key);
  if (value == nullptr) throw Error(entry(key) + " has not been written");
  if (std::type_index(value->type()) == type || type == std::type_index(typeid(std::any))) {
    return *value;
  }
  if (std::type_index(value->type()) == kStringType && converters_->can_parse(type)) {
    const auto& text = std::any_cast<const std::string&>(*value);
    if (auto converted = converters_->parse_text(type, text)) return std::move(*converted);
    throw Error(entry(key) + " holds the text '" + text + "', which is not a valid " +
                type_name(type));
  }
  throw Error(entry(key) + " holds " + type_name(value->type()) + ", not " + type_name(type));
}

std::optional<std::type_index> Blackboard::type_of(const std::string& key) const {
  const std::any* value = find(key);
  if (value == nullptr) return std::nullopt;
  return std::type_index(value->type());
}

std::string Blackboard::text(const std::string& key) const {
  const std::any* value = find(key);
  return value == nullptr ? std::string("<unset>") : converters_->format(*value);
}

std::vector<std::string> Blackboard::keys() const {
  std::vector<std::string> result;
  for (const auto& [key, value] : entries_) result.push_back(key);
  for (const auto& [key, remap] : remaps_) {
    if (has(key) && entries_.count(key) == 0) result.push_back(key);
  }
  std::sort(result.begin(), result.end());
  return result;
}

void Blackboard::remap(const std::string& key, std::shared_ptr<Blackboard> target,
                       std::string target_key) {
  remaps_.insert_or_assign(key, Remap{std::move(target), std::move(target_key)});
}

}  // namespace antipode::bt

namespace antipode::bt {

bool is_valid_key(const std::string& key) {
  if (key.empty()) return false;
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  if (std::isdigit(static_cast<unsigned char>(key[0]))) return false;
  return std::all_of(key.begin(), key.end(), word);
}

std::optional<std::string> parse_reference(const std::string& text) {
  if (text.size() < 2 || text.front() != '{' || text.back() != '}') return std::nullopt;
  std::string key = text.substr(1, text.size() - 2);
  if (!is_valid_key(key)) return std::nullopt;
  return key;
}

}  // namespace antipode::bt
