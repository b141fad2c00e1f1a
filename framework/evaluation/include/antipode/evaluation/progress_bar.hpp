#pragma once
// A one-line progress bar for long tree steps (Node::progress()), drawn on a terminal:
//   training scenes [##########..........]  40/80  0:12 elapsed, 0:12 left
// Written here because Debian packages no C++ progress-bar library, and this one also has to
// step aside for the tree's log lines (clear(), then redraw()).

#include <chrono>
#include <cstddef>
#include <ostream>
#include <string>

#include "antipode/bt/tree.hpp"

namespace antipode::evaluation {

class ProgressBar {
 public:
  /// Draws on `out`; `enabled` false makes every call do nothing (output not a terminal).
  ProgressBar(std::ostream& out, bool enabled);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// Shows `done` of `total` steps of `what`; a new `what` restarts the clock. The line is
  /// finished (newline) when done reaches total.
  void update(std::size_t done, std::size_t total, const std::string& what);
  /// Erases the bar's line (before other output on the terminal).
  void clear();
  /// Draws the bar again after clear().
  void redraw();

 private:
  void draw();
  std::ostream& out_;
  bool enabled_;
  bool shown_ = false;
  std::string what_;
  std::size_t done_ = 0;
  std::size_t total_ = 0;
  std::chrono::steady_clock::time_point started_;
};

/// Sends `tree`'s progress reports to `bar` and its log lines to stdout around the bar.
void attach_progress_bar(bt::Tree& tree, ProgressBar& bar);

/// True when standard error is a terminal (and NO_PROGRESS is not set).
bool progress_wanted();

}  // namespace antipode::evaluation
