#include "antipode/evaluation/progress_bar.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

namespace antipode::evaluation {
namespace {

constexpr int kBarWidth = 24;

std::string clock_text(double seconds) {
  const long total = std::lround(seconds);
  char text[32];
  std::snprintf(text, sizeof(text), "%ld:%02ld", total / 60, total % 60);
  return text;
}

}  // namespace

ProgressBar::ProgressBar(std::ostream& out, bool enabled) : out_(out), enabled_(enabled) {}

ProgressBar::~ProgressBar() {
  if (shown_) out_ << '\n' << std::flush;
}

void ProgressBar::update(std::size_t done, std::size_t total, const std::string& what) {
  if (!enabled_ || total == 0) return;
  if (what != what_ || done < done_) started_ = std::chrono::steady_clock::now();
  what_ = what;
  done_ = std::min(done, total);
  total_ = total;
  draw();
  if (done_ == total_) {
    out_ << '\n' << std::flush;
    shown_ = false;
  }
}

void ProgressBar::clear() {
  if (!shown_) return;
  out_ << "\r\033[K" << std::flush;
}

void ProgressBar::redraw() {
  if (shown_) draw();
}

void ProgressBar::draw() {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  const int filled = static_cast<int>(kBarWidth * done_ / total_);
  std::string line = "\r\033[K" + what_ + " [" +
                     std::string(static_cast<std::size_t>(filled), '#') +
                     std::string(static_cast<std::size_t>(kBarWidth - filled), '.') + "] " +
                     std::to_string(done_) + "/" + std::to_string(total_) + "  " +
                     clock_text(elapsed) + " elapsed";
  if (done_ > 0 && done_ < total_) {
    line += ", " +
            clock_text(elapsed * static_cast<double>(total_ - done_) / static_cast<double>(done_)) +
            " left";
  }
  out_ << line << std::flush;
  shown_ = true;
}

void attach_progress_bar(bt::Tree& tree, ProgressBar& bar) {
  tree.set_progress_sink([&bar](const bt::Node&, std::size_t done, std::size_t total,
                                const std::string& what) { bar.update(done, total, what); });
  tree.set_log_sink([&bar](const bt::Node&, const std::string& message) {
    bar.clear();
    std::cout << message << '\n' << std::flush;
    bar.redraw();
  });
}

bool progress_wanted() {
  return isatty(STDERR_FILENO) != 0 && std::getenv("NO_PROGRESS") == nullptr;
}

}  // namespace antipode::evaluation
