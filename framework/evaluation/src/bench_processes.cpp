#include "antipode/evaluation/bench_processes.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include "antipode/core/error.hpp"
#include "antipode/evaluation/exit_codes.hpp"

namespace fs = std::filesystem;

namespace antipode::evaluation {
namespace {

using Json = nlohmann::ordered_json;

int exit_code_of(const std::exception& error) {
  return dynamic_cast<const Error*>(&error) ? kExitInvalidInput : kExitInternalError;
}

int wait_for(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return kExitInternalError;
}

// The body of worker `job`: its share of the tasks, each record a line of its file.
int run_share(const fs::path& file_path, const std::vector<std::size_t>& tasks, int job, int jobs,
              const BenchTaskRunner& run, const BenchProgressLine& progress) {
  try {
    std::ofstream file(file_path);
    const Session session = open_session();
    for (std::size_t k = std::size_t(job); k < tasks.size(); k += std::size_t(jobs)) {
      const Json record = run(session, tasks[k]);
      file << record.dump() << "\n" << std::flush;
      const std::string line = progress(record);
      if (::write(STDOUT_FILENO, line.data(), line.size()) < 0) return kExitInternalError;
    }
    return kExitSuccess;
  } catch (const std::exception& error) {
    std::cerr << "antipode: error: " << error.what() << "\n";
    return exit_code_of(error);
  }
}

// The records of `tasks` in their order (null where a worker wrote none).
std::vector<Json> read_records(const fs::path& folder, const std::vector<std::size_t>& tasks,
                               int jobs) {
  std::map<std::size_t, Json> by_task;
  for (int job = 0; job < jobs; ++job) {
    std::ifstream file(folder / ("job-" + std::to_string(job) + ".jsonl"));
    for (std::string line; std::getline(file, line);) {
      Json record = Json::parse(line);
      const auto index = record.at("task").get<std::size_t>();
      by_task[index] = std::move(record);
    }
  }
  std::vector<Json> records;
  records.reserve(tasks.size());
  for (const std::size_t task : tasks) records.push_back(std::move(by_task[task]));
  return records;
}

}  // namespace

void check_in_child(const std::function<void(const Session&)>& check) {
  std::cout.flush();
  const pid_t pid = fork();
  if (pid < 0) throw Error("cannot start a benchmark process");
  if (pid == 0) {
    int code = kExitSuccess;
    try {
      check(open_session());
    } catch (const std::exception& error) {
      std::cerr << "antipode: error: " << error.what() << "\n";
      code = exit_code_of(error);
    }
    std::_Exit(code);
  }
  if (const int code = wait_for(pid); code != kExitSuccess) throw BenchStopped{code};
}

std::vector<Json> run_bench_tasks(const std::vector<std::size_t>& tasks, int jobs,
                                  const BenchTaskRunner& run, const BenchProgressLine& progress) {
  if (jobs == 1) {
    const Session session = open_session();
    std::vector<Json> records;
    for (const std::size_t task : tasks) {
      records.push_back(run(session, task));
      std::cout << progress(records.back()) << std::flush;
    }
    return records;
  }
  std::string pattern = (fs::temp_directory_path() / "antipode-bench-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw Error("cannot create a temporary folder");
  const fs::path folder = pattern;
  std::cout.flush();
  std::vector<pid_t> children;
  for (int job = 0; job < jobs; ++job) {
    const pid_t pid = fork();
    if (pid < 0) throw Error("cannot start a benchmark process");
    if (pid == 0) {
      const fs::path file = folder / ("job-" + std::to_string(job) + ".jsonl");
      std::_Exit(run_share(file, tasks, job, jobs, run, progress));
    }
    children.push_back(pid);
  }
  int failed = 0;
  for (const pid_t pid : children)
    if (const int code = wait_for(pid); code != kExitSuccess) failed = code;
  std::vector<Json> records = read_records(folder, tasks, jobs);
  fs::remove_all(folder);
  if (failed != 0) throw Error("a benchmark process failed (see its message above)");
  for (const Json& record : records)
    if (record.is_null()) throw InternalError("a benchmark process lost a task");
  return records;
}

}  // namespace antipode::evaluation
