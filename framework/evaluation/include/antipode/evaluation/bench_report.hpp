#pragma once
// Tallies of benchmark attempts: success rates with 95% intervals per variant, object and
// group, failure classes, seconds per stage; printed as tables and written as JSON.

#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace antipode::evaluation {

/// The value at fraction `p` (0..1) of `values` sorted, interpolated linearly between the two
/// nearest ranks (so the median of an even count is the mean of the middle two); 0 for none.
double percentile(std::vector<double> values, double p);

/// The Wilson score interval (95%) of `successes` in `trials`: {lower, upper}, {0, 1} for
/// no trials.
std::pair<double, double> wilson_interval(int successes, int trials);

/// The "summary" of a report: for each variant of `variants` (in that order) its counts over
/// `attempts` (records as run_task() makes them): attempts, successes, no_grasp, success_rate
/// with ci95, found_grasp (the rate over attempts where a grasp was found, as the paper
/// counts A 2V), per_object_mean (the mean of the objects' rates, as the paper averages),
/// outcomes and reasons (failure classes), groups (graspable / not_graspable, tuning /
/// held_out, each with attempts, successes, success_rate, ci95, per_object_mean), fidelity
/// (executed attempts on graspable objects: as_detected - the hand reached its pose or the
/// record names what stopped it - and held, their rates) and stage_s_median.
nlohmann::ordered_json summarise(const nlohmann::ordered_json& attempts,
                                 const std::vector<std::string>& variants);

/// Prints the per-object table (successes / attempts per variant, then the per-object mean
/// and the pooled rate with its interval per group), the failure classes and the seconds per
/// stage.
void print_report(std::ostream& out, const nlohmann::ordered_json& attempts,
                  const nlohmann::ordered_json& summary, const std::vector<std::string>& variants);

/// The machine a bench runs on: {"cpu": the processor's model name, "cores", "system": kernel
/// name, release and architecture}.
nlohmann::ordered_json machine_json();

/// Adds how a bench ran to its report: "jobs" (processes), "threads_per_job", "cores",
/// "machine" (machine_json()) and "wall_s".
void add_how_it_ran(nlohmann::ordered_json& report, int jobs, int threads_per_job, int cores,
                    double wall_s);

/// Writes `report` to `path` (all or nothing) and prints "report: PATH"; nothing when `path`
/// is empty. Throws antipode::Error naming the file when it cannot be written.
void write_report(std::ostream& out, const std::string& path, const nlohmann::ordered_json& report);

}  // namespace antipode::evaluation
