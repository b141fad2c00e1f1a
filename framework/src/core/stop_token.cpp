#include "antipode/core/stop_token.hpp"

namespace antipode {

void StopToken::throw_if_stop_requested(const std::string& where) const {
  if (!stop_requested()) return;
  const bool by_source = flag_ && flag_->load(std::memory_order_relaxed);
  throw Cancelled(where + ": cancelled (" +
                  (by_source ? "a stop was requested" : "the time limit ran out") + ")");
}

StopToken StopToken::with_deadline(Clock::time_point deadline) const {
  StopToken t = *this;
  if (!t.deadline_ || deadline < *t.deadline_) t.deadline_ = deadline;
  return t;
}

}  // namespace antipode
