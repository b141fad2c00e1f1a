#pragma once
// The commands that run the evaluation library's engines: the benches, their merge, outcome
// data and the results report. Each returns the process exit code (exit_codes.hpp) and
// throws antipode::Error for bad input, which main() prints as one line.

#include "antipode/evaluation/bench_merge.hpp"
#include "antipode/evaluation/clutter_bench.hpp"
#include "antipode/evaluation/isolation_bench.hpp"
#include "antipode/evaluation/markdown_report.hpp"
#include "antipode/evaluation/outcome_data.hpp"
#include "antipode/evaluation/reach_bench.hpp"

namespace antipode::cli {

/// Exit 3 when an attempt ended in an error (it measured nothing).
int bench_isolation_command(const evaluation::IsolationBenchOptions& options);
/// Exit 3 when a run ended in an error.
int bench_clutter_command(const evaluation::ClutterBenchOptions& options);
int bench_reach_command(const evaluation::ReachBenchOptions& options);
int bench_merge_command(const evaluation::BenchMergeOptions& options);
/// Exit 1 when a scene ended in an error (running again retries it).
int outcome_data_command(const evaluation::OutcomeDataOptions& options);
int report_command(const evaluation::ReportOptions& options);

}  // namespace antipode::cli
