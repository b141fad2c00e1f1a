// `antipode bench isolation|clutter|reach|merge`, `antipode outcomes` and `antipode report`:
// each calls its engine in the evaluation library, writes what it returns and turns the
// result into the exit code.

#include <iostream>

#include "antipode/evaluation/bench_processes.hpp"
#include "antipode/evaluation/bench_report.hpp"
#include "antipode/evaluation/exit_codes.hpp"
#include "bench_commands.hpp"

namespace antipode::cli {
namespace {

using evaluation::kExitInternalError;
using evaluation::kExitSuccess;
using evaluation::kExitTreeFailed;

// Writes `report` to `path` unless it is "" (the report's path was checked before the run).
void write_if_named(const std::string& path, const nlohmann::ordered_json& report) {
  if (!path.empty()) evaluation::write_report(std::cout, path, report);
}

// Runs `bench`; a worker process that stopped it already printed why: its exit code is ours.
template <typename Bench>
int stopped_or(Bench bench) {
  try {
    return bench();
  } catch (const evaluation::BenchStopped& stopped) {
    return stopped.code;
  }
}

}  // namespace

int bench_isolation_command(const evaluation::IsolationBenchOptions& options) {
  return stopped_or([&] {
    const auto report = evaluation::run_isolation_bench(options);
    write_if_named(options.report_path, report);
    // An attempt whose tree raised an error measured nothing: the bench must not pass for one.
    return evaluation::has_errors(report) ? kExitInternalError : kExitSuccess;
  });
}

int bench_clutter_command(const evaluation::ClutterBenchOptions& options) {
  return stopped_or([&] {
    const auto report = evaluation::run_clutter_bench(options);
    write_if_named(options.report_path, report);
    return report.at("summary").at("errors").get<int>() > 0 ? kExitInternalError : kExitSuccess;
  });
}

int bench_reach_command(const evaluation::ReachBenchOptions& options) {
  write_if_named(options.report_path, evaluation::run_reach_bench(options));
  return kExitSuccess;
}

int bench_merge_command(const evaluation::BenchMergeOptions& options) {
  write_if_named(options.report_path, evaluation::run_bench_merge(options));
  return kExitSuccess;
}

int outcome_data_command(const evaluation::OutcomeDataOptions& options) {
  return stopped_or(
      [&] { return evaluation::run_outcome_data(options) > 0 ? kExitTreeFailed : kExitSuccess; });
}

int report_command(const evaluation::ReportOptions& options) {
  const std::string charts = evaluation::write_markdown_report(options);
  std::cout << "report: " << options.out_path << " (" << options.reports.size()
            << " bench reports, charts in " << charts << ")\n";
  return kExitSuccess;
}

}  // namespace antipode::cli
