#include "antipode/core/error.hpp"

#include <algorithm>

namespace antipode {
namespace {

std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  return text.empty() ? std::string("unknown error") : text;
}

std::string compose(const std::string& message, const SourceLocation& where,
                    const std::string& hint) {
  std::string text = where.known() ? where.str() + ": " : std::string();
  text += message;
  if (!hint.empty()) text += " (" + hint + ")";
  return one_line(text);
}

// Levenshtein distance; names are short, so the O(n*m) table is fine.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
    }
  }
  return row[b.size()];
}

}  // namespace

std::string SourceLocation::str() const {
  if (file.empty()) return {};
  std::string text = file;
  if (line > 0) text += ":" + std::to_string(line);
  if (line > 0 && column > 0) text += ":" + std::to_string(column);
  return text;
}

Error::Error(const std::string& message, SourceLocation where, std::string hint)
    : std::runtime_error(compose(message, where, hint)),
      message_(message),
      where_(std::move(where)),
      hint_(std::move(hint)) {}

void rethrow_with_context(const std::string& who, const SourceLocation& where) {
  try {
    throw;
  } catch (const InternalError& error) {
    if (error.where().known()) throw;
    throw InternalError(who + ": " + error.message(), where, error.hint());
  } catch (const Error& error) {
    if (error.where().known()) throw;
    throw Error(who + ": " + error.message(), where, error.hint());
  } catch (const std::exception& error) {
    throw InternalError(who + ": " + error.what(), where);
  } catch (...) {
    throw InternalError(who + ": an exception of unknown type", where);
  }
}

std::string closest_match(const std::string& name, const std::vector<std::string>& candidates) {
  const std::size_t limit = std::max<std::size_t>(2, name.size() / 3);
  std::string best;
  std::size_t best_distance = limit + 1;
  for (const auto& candidate : candidates) {
    const std::size_t distance = edit_distance(name, candidate);
    if (distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates) {
  const std::string best = closest_match(name, candidates);
  return best.empty() ? std::string() : " (did you mean '" + best + "'?)";
}

}  // namespace antipode
