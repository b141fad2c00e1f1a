#pragma once
/// @file
/// Cooperative cancellation: a StopToken tells a long call (sampling, classification,
/// selection, planning) that its caller no longer wants the answer - a `Timeout` node's
/// deadline passed, or someone asked the tree to stop.
///
/// Contract for callees: poll stop_requested() between the stages of their work (a planner
/// within its search loop) and, when it is true, return promptly - by throw_if_stop_requested()
/// (which throws Cancelled), or with a status that says so where the interface has one
/// (MotionPlanner). Results of a cancelled call are never partial: a callee either finishes or
/// reports the cancellation.
///
/// Threads: a token is a small value; copies share their source, and stop_requested() may be
/// called from any thread concurrently with StopSource::request_stop().

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "antipode/core/error.hpp"

namespace antipode {

/// Thrown by StopToken::throw_if_stop_requested(): the call was cancelled, its work dropped.
class Cancelled : public Error {
 public:
  using Error::Error;
};

class StopToken {
 public:
  using Clock = std::chrono::steady_clock;

  /// A token that never asks to stop.
  StopToken() = default;

  /// True once the deadline (if any) has passed or the source (if any) requested a stop.
  bool stop_requested() const {
    if (flag_ && flag_->load(std::memory_order_relaxed)) return true;
    return deadline_ && Clock::now() >= *deadline_;
  }
  /// Throws Cancelled("<where>: cancelled (<why>)") when stop_requested().
  void throw_if_stop_requested(const std::string& where) const;

  /// This token, also stopping at `deadline` (the earlier of both deadlines).
  StopToken with_deadline(Clock::time_point deadline) const;

 private:
  friend class StopSource;
  std::shared_ptr<const std::atomic<bool>> flag_;
  std::optional<Clock::time_point> deadline_;
};

/// The owner's side: request_stop() makes every token of this source ask to stop.
class StopSource {
 public:
  StopSource() : flag_(std::make_shared<std::atomic<bool>>(false)) {}
  void request_stop() { flag_->store(true, std::memory_order_relaxed); }
  StopToken token() const {
    StopToken t;
    t.flag_ = flag_;
    return t;
  }

 private:
  std::shared_ptr<std::atomic<bool>> flag_;
};

}  // namespace antipode
