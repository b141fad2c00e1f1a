#include "rejection_summary.hpp"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace antipode::pipeline {

std::string rejection_summary(const HandSet& hands, bool count_kept) {
  std::map<std::string, int> count;
  for (const Hand& hand : hands.hands)
    if (count_kept || hand.rejection != Rejection::kNone) ++count[to_string(hand.rejection)];
  std::vector<std::pair<int, std::string>> order;
  for (const auto& [reason, n] : count) order.emplace_back(-n, reason);
  std::sort(order.begin(), order.end());
  std::string text;
  for (const auto& [n, reason] : order)
    text += (text.empty() ? "" : ", ") + std::to_string(-n) + " " + reason;
  return text.empty() ? "no hands" : text;
}

}  // namespace antipode::pipeline
