#pragma once
// Running a benchmark's tasks in forked processes: each process opens its own session (plugins
// and nodes), runs every task whose position in the list is its number modulo the process
// count, and writes one JSON record per task; the records come back in task order, so a
// report is the same for any number of processes.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "antipode/evaluation/session.hpp"

namespace antipode::evaluation {

/// A child process already printed why the run cannot go on; exit with its code.
struct BenchStopped {
  int code;
};

/// Runs task `index` in `session` and returns its record.
using BenchTaskRunner = std::function<nlohmann::ordered_json(const Session&, std::size_t index)>;
/// One progress line (with its newline) for a finished task's record.
using BenchProgressLine = std::function<std::string(const nlohmann::ordered_json&)>;

/// Runs `check` in a child process (so that this one starts no plugin before forking its
/// workers); an error there is printed once and thrown here as BenchStopped.
void check_in_child(const std::function<void(const Session&)>& check);

/// Runs the tasks numbered in `tasks` in `jobs` processes (in this one when `jobs` is 1),
/// printing each record's progress line as it finishes; returns the records in the order of
/// `tasks`. Throws antipode::Error when a process failed (its message printed above).
std::vector<nlohmann::ordered_json> run_bench_tasks(const std::vector<std::size_t>& tasks, int jobs,
                                                    const BenchTaskRunner& run,
                                                    const BenchProgressLine& progress);

}  // namespace antipode::evaluation
