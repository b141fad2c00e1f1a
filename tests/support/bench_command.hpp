#pragma once
// Test helper: a fixture that runs `antipode bench SUBCOMMAND ...` from the source tree (where
// the trees are) with a temporary folder of its own for reports.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/command_output.hpp"
#include "support/without_seconds.hpp"

namespace antipode::testing {

class BenchCommandTest : public ::testing::Test {
 protected:
  /// `subcommand`: "isolation", "clutter", ...
  explicit BenchCommandTest(std::string subcommand) : subcommand_(std::move(subcommand)) {}

  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("antipode_bench_" + subcommand_ + "_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  /// Runs `antipode ARGUMENTS` (any command) from the source tree.
  CommandResult antipode(const std::string& arguments) const {
    return run_command("cd '" + std::string(ANTIPODE_TEST_SOURCE_DIR) + "' && " +
                       std::string(ANTIPODE_CLI) + " " + arguments);
  }

  /// Runs `antipode bench SUBCOMMAND ARGUMENTS`.
  CommandResult bench(const std::string& arguments) const {
    return antipode("bench " + subcommand_ + " " + arguments);
  }

  /// DIR/NAME: a file in the test's own temporary folder.
  std::string file(const std::string& name) const { return (dir_ / name).string(); }

  /// Runs it with `--report DIR/NAME`, expects exit 0 and returns the report (null if none).
  nlohmann::json report(const std::string& arguments, const std::string& name) const {
    const std::string path = file(name);
    const CommandResult result = bench(arguments + " --report " + path);
    EXPECT_EQ(result.exit_code, 0) << result.out;
    std::ifstream in(path);
    return in ? nlohmann::json::parse(in) : nlohmann::json();
  }

  /// Expects `arguments` to fail with exit 2 and one "antipode: error: " line holding `words`.
  void expect_error(const std::string& arguments, const std::string& words) const {
    const CommandResult r = bench(arguments);
    EXPECT_EQ(r.exit_code, 2) << arguments << ": " << r.out;
    EXPECT_NE(r.out.find("antipode: error: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(words), std::string::npos) << arguments << ": " << r.out;
  }

 private:
  std::string subcommand_;
  std::filesystem::path dir_;
};

}  // namespace antipode::testing
