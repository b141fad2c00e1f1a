// The job scripts of scripts/slurm/ on a real Slurm: a one-machine cluster
// (scripts/slurm/local-cluster: MUNGE, slurmctld and slurmd from Debian's packages, on ports
// it checks are free) that each test starts and stops, by process id, whatever the outcome.
// A clutter bench runs as an array job of shards (`--shard auto`) and a merge that waits for
// them (`--dependency=afterok`): the merged summary equals the bench run in one process.
// Outcome data runs as an array too, then the training: the trials are those of one process.
// A merge after a failed shard never starts.
#include <unistd.h>

#include <signal.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "support/bench_command.hpp"

namespace {
using antipode::testing::CommandResult;
using antipode::testing::run_command;
using antipode::testing::without_seconds;

class SlurmTest : public antipode::testing::BenchCommandTest {
 protected:
  SlurmTest() : BenchCommandTest("isolation") {}

  void SetUp() override {
    BenchCommandTest::SetUp();
    if (::geteuid() != 0) GTEST_SKIP() << "slurmd starts jobs as their users: it needs root";
    const CommandResult started = script("local-cluster start " + file("cluster"));
    ASSERT_EQ(started.exit_code, 0) << started.out;
    running_ = true;
  }

  // Stops the cluster, and checks that none of its daemons is left and that neither its
  // folder of sockets nor the test's folder is.
  void TearDown() override {
    std::vector<int> daemons;
    for (const char* pid_file :
         {"cluster/slurmctld.pid", "cluster/slurmd.pid", "cluster/munge/munged.pid"}) {
      std::ifstream in(file(pid_file));
      int pid = 0;
      if (in >> pid) daemons.push_back(pid);
    }
    std::string runtime;  // the cluster's short folder of sockets, outside the test's
    std::ifstream(file("cluster/runtime")) >> runtime;
    if (running_) script("local-cluster stop " + file("cluster"));
    for (const int pid : daemons) EXPECT_NE(::kill(pid, 0), 0) << "daemon " << pid << " is left";
    if (!runtime.empty()) {
      EXPECT_FALSE(std::filesystem::exists(runtime)) << runtime << " is left";
    }
    BenchCommandTest::TearDown();
    EXPECT_FALSE(std::filesystem::exists(file(""))) << "the test's folder is left";
  }

  // scripts/slurm/ARGUMENTS, run from the source tree with the cluster's configuration and
  // the build's antipode.
  CommandResult script(const std::string& arguments) const {
    return run_command("cd '" + std::string(ANTIPODE_TEST_SOURCE_DIR) + "' && SLURM_CONF='" +
                       file("cluster/etc/slurm.conf") + "' ANTIPODE='" + ANTIPODE_CLI +
                       "' scripts/slurm/" + arguments);
  }

  // squeue's state and reason of job `id` ("" once it has left the queue).
  std::string queued(const std::string& id) const {
    const CommandResult r = run_command("SLURM_CONF='" + file("cluster/etc/slurm.conf") +
                                        "' squeue -h -o '%T %r' -j " + id + " 2>/dev/null");
    return r.out;
  }

  // Waits until job `id` has left the queue (at most `limit`); false if it has not.
  bool finished(const std::string& id, std::chrono::seconds limit) const {
    const auto end = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < end) {
      if (queued(id).empty()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(500));
    }
    return false;
  }

  bool running_ = false;
};

std::string last_line(const std::string& text) {
  std::string trimmed = text;
  while (!trimmed.empty() && trimmed.back() == '\n') trimmed.pop_back();
  return trimmed.substr(trimmed.rfind('\n') == std::string::npos ? 0 : trimmed.rfind('\n') + 1);
}

TEST_F(SlurmTest, AClutterBenchRunsAsAnArrayJobAndAMergeAfterIt) {
  const std::string args = "clutter --objects procedural --runs 2 --objects-per-run 3";
  const auto whole = antipode("bench " + args + " --report " + file("whole.json"));
  ASSERT_EQ(whole.exit_code, 0) << whole.out;
  const CommandResult submitted = script("submit-bench 2 " + file("grid") + " " + args + " 2>&1");
  ASSERT_EQ(submitted.exit_code, 0) << submitted.out;
  const std::string merge_job = last_line(submitted.out);
  ASSERT_TRUE(finished(merge_job, std::chrono::seconds(240))) << queued(merge_job);
  std::ifstream in(file("grid/bench.json"));
  ASSERT_TRUE(in) << "no merged report; the jobs' output is in " << file("grid");
  const auto merged = nlohmann::json::parse(in);
  std::ifstream whole_in(file("whole.json"));
  const auto one_process = nlohmann::json::parse(whole_in);
  EXPECT_EQ(merged["run_records"].size(), 2u);
  EXPECT_EQ(without_seconds(merged["summary"]), without_seconds(one_process["summary"]));
  for (const char* shard : {"grid/shard-1.json", "grid/shard-2.json"}) {
    std::ifstream part(file(shard));
    ASSERT_TRUE(part) << shard;
    EXPECT_EQ(nlohmann::json::parse(part)["shard"]["count"], 2) << shard;
  }
}

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST_F(SlurmTest, OutcomeDataRunsAsAnArrayJobAndTheTrainingAfterIt) {
  const std::string args = "--scenes 2 --first-seed 100000";
  const auto direct = antipode("outcomes " + args + " --out " + file("direct"));
  ASSERT_EQ(direct.exit_code, 0) << direct.out;
  const CommandResult submitted = script("submit-outcomes 2 " + file("data") + " " + args +
                                         " -- --set calibration=" + file("direct") + " 2>&1");
  ASSERT_EQ(submitted.exit_code, 0) << submitted.out;
  const std::string train_job = last_line(submitted.out);
  ASSERT_TRUE(finished(train_job, std::chrono::seconds(240))) << queued(train_job);
  for (const char* name :
       {"scene-100000.json", "scene-100001.json", "scene-100000.data", "scene-100001.data"}) {
    const std::string sharded = contents(file("data/trials/") + name);
    EXPECT_FALSE(sharded.empty()) << name;
    EXPECT_EQ(sharded, contents(file("direct/") + name)) << name;
  }
  EXPECT_TRUE(std::filesystem::exists(file("data/outcome.model")))
      << contents(file("data/slurm-" + train_job + ".out"));
}

TEST_F(SlurmTest, AMergeAfterAFailedShardNeverStarts) {
  const CommandResult submitted =
      script("submit-bench 2 " + file("bad") + " isolation --variants svm_2w 2>&1");
  ASSERT_EQ(submitted.exit_code, 0) << submitted.out;
  const std::string merge_job = last_line(submitted.out);
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  std::string state;
  while (std::chrono::steady_clock::now() < end) {
    state = queued(merge_job);
    if (state.find("DependencyNeverSatisfied") != std::string::npos) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
  EXPECT_NE(state.find("PENDING DependencyNeverSatisfied"), std::string::npos) << state;
  run_command("SLURM_CONF='" + file("cluster/etc/slurm.conf") + "' scancel " + merge_job);
  EXPECT_FALSE(std::ifstream(file("bad/bench.json")));
  const CommandResult shard_log = run_command("cat " + file("bad") + "/slurm-*_1.out");
  EXPECT_NE(shard_log.out.find("did you mean 'svm_2v'"), std::string::npos) << shard_log.out;
}

}  // namespace
