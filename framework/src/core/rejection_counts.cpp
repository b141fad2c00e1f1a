#include <algorithm>
#include <cctype>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "antipode/core/hand.hpp"

namespace antipode {

void reject_for(Hand& hand, std::string reason) {
  for (char& c : reason)
    if (std::iscntrl(static_cast<unsigned char>(c))) c = ' ';  // reasons are one line
  // A code's name ("none", "low score") would be counted as that code: it is marked as the
  // plugin's.
  for (int code = 0; code <= static_cast<int>(Rejection::kPluginReason); ++code)
    if (reason == to_string(static_cast<Rejection>(code))) reason += " (a plugin's)";
  hand.rejection = Rejection::kPluginReason;
  hand.rejection_text = std::move(reason);
}

std::string rejection_reason(const Hand& hand) {
  if (hand.rejection == Rejection::kPluginReason && !hand.rejection_text.empty())
    return hand.rejection_text;
  return to_string(hand.rejection);
}

std::string rejection_counts(const std::vector<Hand>& hands, bool count_kept) {
  std::map<std::string, int> count;
  for (const Hand& hand : hands)
    if (count_kept || hand.rejection != Rejection::kNone) ++count[rejection_reason(hand)];
  std::vector<std::pair<int, std::string>> order;
  for (const auto& [reason, n] : count) order.emplace_back(-n, reason);
  std::sort(order.begin(), order.end());
  std::string text;
  for (const auto& [n, reason] : order)
    text += (text.empty() ? "" : ", ") + std::to_string(-n) + " " + reason;
  return text.empty() ? "no hands" : text;
}

}  // namespace antipode
