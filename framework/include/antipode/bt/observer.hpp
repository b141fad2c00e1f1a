#pragma once
/// @file
/// What a running tree reports: node status changes (to observers such as the tracers) and
/// Log messages (to a log sink).

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>

#include "antipode/bt/status.hpp"

namespace antipode::bt {

class Node;

/// Receives every status change of every node of a tree it is attached to
/// (Tree::add_observer), in the order they happen, in the thread that ticks the tree.
///
/// Reported: any change to RUNNING, SUCCESS or FAILURE, and RUNNING -> IDLE (the node was
/// halted). Not reported: the SUCCESS/FAILURE -> IDLE resets that follow completion.
/// Node::failure_reason() is set when `current` is kFailure and the node gave a reason.
class TreeObserver {
 public:
  virtual ~TreeObserver() = default;
  virtual void on_status_change(const Node& node, Status previous, Status current,
                                std::chrono::steady_clock::time_point when) = 0;
};

/// Another name for an observer that records what it sees.
using Tracer = TreeObserver;

/// Where Log nodes (and Node::log()) send messages; the default prints the message and a
/// newline to stdout.
using LogSink = std::function<void(const Node& node, const std::string& message)>;

/// Where long-running nodes report how far they are (Node::progress()): `done` of `total`
/// steps of `what` ("training scenes", "cross-validation"). The default ignores reports;
/// the CLI draws a progress bar on a terminal.
using ProgressSink = std::function<void(const Node& node, std::size_t done, std::size_t total,
                                        const std::string& what)>;

}  // namespace antipode::bt
