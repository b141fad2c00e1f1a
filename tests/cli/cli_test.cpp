// The `antipode` command as a user meets it: exit codes, one-line errors, plugin listings.
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "antipode/grasp/svm_model.hpp"
#include "antipode/grasp/training_set.hpp"
#include "support/command_output.hpp"

namespace {
namespace fs = std::filesystem;

using Result = antipode::testing::CommandResult;

// Runs the CLI with `arguments` (shell words) and `environment` ("A=b " prefixes).
Result run(const std::string& arguments, const std::string& environment = "") {
  return antipode::testing::run_command(environment + " " + std::string(ANTIPODE_CLI) + " " +
                                        arguments);
}

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("antipode_cli_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path.string();
  }

  fs::path dir_;
};

const std::string kGoodPlugins = "ANTIPODE_PLUGIN_PATH=" + std::string(FIXTURE_DIR) + "/good";

TEST_F(CliTest, ValidateReportsMisspeltNodeWithLocationAndSuggestion) {
  const std::string tree = write("x.yaml",
                                 "main: t\n"
                                 "trees:\n"
                                 "  t:\n"
                                 "    Sequnce:\n"
                                 "      - AlwaysSuccess: {}\n");
  const Result result = run("validate " + tree);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "antipode: error: " + tree +
                            ":4:5: unknown node 'Sequnce' (did you mean 'Sequence'?)\n");
}

TEST_F(CliTest, ValidateChecksEveryTreeGivenAndStopsAtTheFirstError) {
  const std::string good = write("good.yaml", "main: t\ntrees:\n  t:\n    AlwaysSuccess: {}\n");
  const std::string bad = write("bad.yaml", "main: t\ntrees:\n  t:\n    AlwaysSucess: {}\n");
  Result result = run("validate " + good + " " + good);
  EXPECT_EQ(result.exit_code, 0) << result.out;
  EXPECT_EQ(std::count(result.out.begin(), result.out.end(), '\n'), 2) << result.out;
  result = run("validate " + good + " " + bad + " " + good);
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("did you mean 'AlwaysSuccess'"), std::string::npos) << result.out;
  EXPECT_EQ(std::count(result.out.begin(), result.out.end(), '\n'), 2) << result.out;
}

TEST_F(CliTest, ValidateAcceptsAGoodTree) {
  const std::string tree = write("ok.yaml", "main: t\ntrees:\n  t:\n    AlwaysSuccess: {}\n");
  const Result result = run("validate " + tree);
  EXPECT_EQ(result.exit_code, 0) << result.out;
  EXPECT_EQ(result.out, tree + ": valid\n");
}

// validate checks a component's parameters as loading it would, through the plugin's
// parameter check, without building it.
TEST_F(CliTest, ValidateChecksComponentParameters) {
  const std::string tree =
      write("c.yaml",
            "components:\n"
            "  classifier: { plugin: antipodal_classifier, max_angle_degs: 20 }\n"
            "main: t\ntrees:\n  t:\n    AlwaysSuccess: {}\n");
  Result result = run("validate " + tree);
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("unknown parameter 'max_angle_degs' of component 'classifier' "
                            "(did you mean 'max_angle_deg'?)"),
            std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find(tree + ":2:"), std::string::npos) << result.out;
  result = run("validate " + tree + " --set classifier.max_angle_degs=20");
  EXPECT_EQ(result.exit_code, 2) << result.out;
  const std::string fixed =
      write("f.yaml",
            "components:\n"
            "  classifier: { plugin: antipodal_classifier, max_angle_deg: 20 }\n"
            "main: t\ntrees:\n  t:\n    AlwaysSuccess: {}\n");
  result = run("validate " + fixed);
  EXPECT_EQ(result.exit_code, 0) << result.out;
}

TEST_F(CliTest, RunUsesAPluginNodeAndReportsSuccess) {
  const std::string tree = write("count.yaml",
                                 "main: t\n"
                                 "trees:\n"
                                 "  t:\n"
                                 "    Sequence:\n"
                                 "      - CountTicks: { count: \"{n}\" }\n"
                                 "      - Log: { message: \"ticked {n} time(s)\" }\n");
  const Result result = run("run --quiet " + tree, kGoodPlugins);
  EXPECT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("ticked 1 time(s)"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find(": SUCCESS"), std::string::npos) << result.out;
}

TEST_F(CliTest, FailingTreeExitsWithOne) {
  const std::string tree = write("fail.yaml", "main: t\ntrees:\n  t:\n    AlwaysFailure: {}\n");
  const Result result = run("run --quiet " + tree);
  EXPECT_EQ(result.exit_code, 1) << result.out;
  EXPECT_NE(result.out.find(": FAILURE"), std::string::npos) << result.out;
}

TEST_F(CliTest, TraceFileIsJsonLines) {
  const std::string tree = write("trace.yaml",
                                 "main: t\ntrees:\n  t:\n    Sequence:\n"
                                 "      - AlwaysSuccess: {}\n      - AlwaysFailure: {}\n");
  const std::string trace = (dir_ / "trace.jsonl").string();
  const Result result = run("run --quiet --trace " + trace + " " + tree);
  EXPECT_EQ(result.exit_code, 1) << result.out;
  std::ifstream in(trace);
  std::vector<nlohmann::json> events;
  for (std::string line; std::getline(in, line);) {
    events.push_back(nlohmann::json::parse(line));  // throws on a malformed line
  }
  // The Sequence starts, both leaves finish at once, then it fails with the second one.
  ASSERT_EQ(events.size(), 4u);
  EXPECT_EQ(events[0]["node"], "Sequence");
  EXPECT_EQ(events[0]["to"], "RUNNING");
  EXPECT_EQ(events[1]["node"], "AlwaysSuccess");
  EXPECT_EQ(events[2]["to"], "FAILURE");
  EXPECT_EQ(events[3]["node"], "Sequence");
  EXPECT_EQ(events[3]["from"], "RUNNING");
  EXPECT_EQ(events[3]["to"], "FAILURE");
}

// eval-classifier's tree reads the model only after computing every example: a damaged model
// is refused before the tree starts (the tree here would log and succeed).
TEST_F(CliTest, EvalClassifierRefusesADamagedModelBeforeAnyWork) {
  const std::string tree = write("eval.yaml",
                                 "main: t\ntrees:\n  t:\n    Sequence:\n"
                                 "      - Log: { message: \"evaluating {model_file}\" }\n");
  const std::string shipped = std::string(ANTIPODE_TEST_SOURCE_DIR) + "/models/hog_svm.model";
  std::ifstream in(shipped, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  ASSERT_GT(bytes.size(), 1000u);
  bytes[bytes.size() / 2] ^= 0x10;
  const std::string model = write("damaged.model", bytes);
  const Result damaged = run("eval-classifier --tree " + tree + " --model " + model);
  EXPECT_EQ(damaged.exit_code, 2) << damaged.out;
  EXPECT_NE(damaged.out.find("damaged.model: classifier model file: corrupted (checksum mismatch)"),
            std::string::npos)
      << damaged.out;
  EXPECT_EQ(damaged.out.find("evaluating"), std::string::npos) << damaged.out;
  const Result intact = run("eval-classifier --tree " + tree + " --model " + shipped);
  EXPECT_EQ(intact.exit_code, 0) << intact.out;
  EXPECT_NE(intact.out.find("evaluating " + shipped), std::string::npos) << intact.out;
}

// docs/cli.md opens with a synopsis line per command: every option a command's --help lists
// is on its line (by its long or its short name), so the synopsis cannot fall behind.
TEST_F(CliTest, TheSynopsisInTheDocsListsEveryOption) {
  std::ifstream in(std::string(ANTIPODE_TEST_SOURCE_DIR) + "/docs/cli.md");
  std::map<std::string, std::string> synopsis;  // "bench clutter" -> its line
  for (std::string line; std::getline(in, line);) {
    if (line == "```" && !synopsis.empty()) break;  // the end of the synopsis block
    std::smatch command;
    if (std::regex_search(line, command, std::regex("^antipode ((bench )?[a-z][a-z-]*)")))
      synopsis[command[1]] = line + " ";
  }
  ASSERT_GE(synopsis.size(), 14u);
  const std::regex option_line(R"(^\s+(-[a-z],)?(--[a-z-]+))");
  for (const auto& [command, line] : synopsis) {
    const Result help = run(command + " --help");
    ASSERT_EQ(help.exit_code, 0) << command << ": " << help.out;
    std::istringstream lines(help.out);
    for (std::string entry; std::getline(lines, entry);) {
      std::smatch option;
      if (!std::regex_search(entry, option, option_line) || option[2] == "--help") continue;
      const std::string short_name = option[1].length() ? option[1].str().substr(0, 2) : "";
      const bool listed = line.find(option[2].str() + " ") != std::string::npos ||
                          line.find(option[2].str() + "]") != std::string::npos ||
                          (!short_name.empty() && line.find(short_name) != std::string::npos);
      EXPECT_TRUE(listed) << "docs/cli.md's synopsis of '" << command << "' lacks " << option[2];
    }
  }
}

// Every command that runs a tree takes --set, --seed and -v the same way.
TEST_F(CliTest, TreeCommandsShareSetSeedAndVerbose) {
  for (const char* command : {"run", "detect", "scene", "train", "eval-classifier"}) {
    const Result help = run(std::string(command) + " --help");
    EXPECT_EQ(help.exit_code, 0) << command;
    for (const char* option : {"--set", "--seed", "-v,--verbose"}) {
      EXPECT_NE(help.out.find(option), std::string::npos) << command << " lacks " << option;
    }
  }
  const std::string tree = write("log.yaml",
                                 "main: t\ntrees:\n  t:\n    Sequence:\n"
                                 "      - Log: { message: \"entry is {e}\" }\n");
  // run traces every node with -v only; --set fills a blackboard entry as for the others.
  const Result traced = run("run " + tree + " --set e=one --seed 4 -v");
  EXPECT_EQ(traced.exit_code, 0) << traced.out;
  EXPECT_NE(traced.out.find("entry is one"), std::string::npos) << traced.out;
  EXPECT_NE(traced.out.find("Sequence"), std::string::npos) << traced.out;
  const Result quiet = run("run -q " + tree + " --set e=two");
  EXPECT_EQ(quiet.exit_code, 0) << quiet.out;
  EXPECT_NE(quiet.out.find("entry is two"), std::string::npos) << quiet.out;
  EXPECT_EQ(quiet.out.find("Sequence"), std::string::npos) << quiet.out;
  const Result plain = run("run " + tree + " --set e=three");
  EXPECT_NE(plain.out.find("entry is three"), std::string::npos) << plain.out;
  EXPECT_EQ(plain.out.find("Sequence"), std::string::npos) << plain.out;
}

// `antipode nodes` lists built-in and plugin node types; with a type, its ports.
TEST_F(CliTest, NodesListsTypesAndPorts) {
  const Result list = run("nodes");
  EXPECT_EQ(list.exit_code, 0) << list.out;
  EXPECT_NE(list.out.find("Sequence (control): "), std::string::npos) << list.out;
  EXPECT_NE(list.out.find("CollectExamples (action): "), std::string::npos) << list.out;
  const Result ports = run("nodes CollectExamples");
  EXPECT_EQ(ports.exit_code, 0) << ports.out;
  EXPECT_NE(ports.out.find("single_views (input, list of int, default [0, 1])"), std::string::npos)
      << ports.out;
  EXPECT_NE(ports.out.find("hands (input, "), std::string::npos) << ports.out;
  EXPECT_NE(ports.out.find(", required): labelled hands"), std::string::npos) << ports.out;
  const Result typo = run("nodes SampleHand");
  EXPECT_EQ(typo.exit_code, 2) << typo.out;
  EXPECT_NE(typo.out.find("unknown node 'SampleHand' (did you mean 'SampleHands'?)"),
            std::string::npos)
      << typo.out;
}

TEST_F(CliTest, MissingTreeFileIsOneLineError) {
  const Result result = run("run /nonexistent/tree.yaml");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(std::count(result.out.begin(), result.out.end(), '\n'), 1) << result.out;
  EXPECT_NE(result.out.find("/nonexistent/tree.yaml"), std::string::npos) << result.out;
}

// Command-line mistakes CLI11 finds are one "antipode: error:" line too, exit 2.
TEST_F(CliTest, CommandLineParseErrorsAreOneLineErrors) {
  for (const auto& [arguments, words] :
       {std::pair<std::string, std::string>{"frobnicate", "frobnicate"},
        {"bench clutter --runz 3", "--runz"},
        {"run --seed abc x.yaml", "got 'abc'"},
        {"validate", "trees is required"},
        {"bench frobnicate", "no subcommand 'frobnicate'"},
        {"run --seed -1 x.yaml", "a seed is a whole number from 0 to 18446744073709551615"},
        {"run --seed '' x.yaml", "got ''"},
        {"bench clutter --seed 123456789012345678901234", "a seed is a whole number"}}) {
    const Result result = run(arguments);
    EXPECT_EQ(result.exit_code, 2) << arguments << ": " << result.out;
    EXPECT_EQ(std::count(result.out.begin(), result.out.end(), '\n'), 1) << result.out;
    EXPECT_EQ(result.out.rfind("antipode: error: ", 0), 0u) << result.out;
    EXPECT_NE(result.out.find(words), std::string::npos) << arguments << ": " << result.out;
  }
  EXPECT_EQ(run("--help").exit_code, 0);
}

// A folder where a file is expected (a tree, a model, a scene) is one clear error.
TEST_F(CliTest, AFolderGivenAsAnInputFileIsOneLineError) {
  const Result tree = run("run /tmp");
  EXPECT_EQ(tree.exit_code, 2) << tree.out;
  EXPECT_NE(tree.out.find("not a regular file (a folder): give a tree file"), std::string::npos)
      << tree.out;
  EXPECT_EQ(std::count(tree.out.begin(), tree.out.end(), '\n'), 1) << tree.out;
}

// A blackboard entry the tree never reads is a mistake, usually a parameter without its
// component: named, with the component whose parameter it is.
TEST_F(CliTest, AnEntryNoNodeReadsIsAnErrorThatNamesTheParameter) {
  const std::string tree =
      write("entry.yaml",
            "components:\n  cell: { plugin: none, samples: 3 }\nmain: t\ntrees:\n  t:\n"
            "    Log: { message: \"{greeting}\" }\n");
  Result result = run("run --quiet " + tree + " --set samples=10");
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("--set samples=10: " + tree +
                            " never reads {samples} (did you mean cell.samples?)"),
            std::string::npos)
      << result.out;
  result = run("run --quiet " + tree + " --set greting=hi");
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("never reads {greting}; a component's parameter is set as"),
            std::string::npos)
      << result.out;
}

TEST_F(CliTest, MalformedSetIsRejected) {
  const std::string tree = write("ok.yaml", "main: t\ntrees:\n  t:\n    AlwaysSuccess: {}\n");
  const Result result = run("run " + tree + " --set novalue");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.out.find("--set 'novalue' must have the form key=value"), std::string::npos)
      << result.out;
}

// A refused library is mentioned where it could be the cause - a type no loaded library
// provides - and nowhere else.
TEST_F(CliTest, UnknownNodeMentionsRefusedPlugins) {
  const std::string bad = "ANTIPODE_PLUGIN_PATH=" + std::string(FIXTURE_DIR) + "/bad";
  const std::string tree = write("x.yaml", "main: t\ntrees:\n  t:\n    CountTick: {}\n");
  Result result = run("validate " + tree, bad);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.out.find("unknown node 'CountTick'"), std::string::npos) << result.out;
  EXPECT_NE(
      result.out.find("plugin libraries were refused, and may provide it; see 'antipode plugins'"),
      std::string::npos)
      << result.out;
  const std::string misspelt =
      write("port.yaml", "main: t\ntrees:\n  t:\n    Log: { mesage: hi }\n");
  result = run("validate " + misspelt, bad);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.out.find("mesage"), std::string::npos) << result.out;
  EXPECT_EQ(result.out.find("refused"), std::string::npos) << result.out;
}

// The dynamic loader names every library it opens (LD_DEBUG=files): a tree opens only the
// plugin libraries it names (the build tree's plugin directory is indexed by the build).
TEST_F(CliTest, ATreeOpensOnlyThePluginsItNames) {
  const std::string empty = write("empty.yaml", "main: t\ntrees:\n  t:\n    AlwaysSuccess: {}\n");
  Result result = run("run --quiet " + empty, "LD_DEBUG=files");
  EXPECT_EQ(result.exit_code, 0) << result.out;
  EXPECT_EQ(result.out.find("libantipode_"), std::string::npos) << result.out;
  const std::string one = write("one.yaml",
                                "components:\n  c: { plugin: passthrough_classifier }\n"
                                "main: t\ntrees:\n  t:\n    AlwaysSuccess: {}\n");
  result = run("run --quiet " + one, "LD_DEBUG=files");
  EXPECT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("libantipode_passthrough_classifier.so"), std::string::npos);
  EXPECT_EQ(result.out.find("libantipode_bullet_cell.so"), std::string::npos);
  EXPECT_EQ(result.out.find("libantipode_hog_svm_classifier.so"), std::string::npos);
  // A plugin named only by --set is found too; ANTIPODE_PLUGIN_LOAD=all opens everything.
  result = run("run --quiet " + one + " --set c.plugin=antipodal_classifier", "LD_DEBUG=files");
  EXPECT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("libantipode_antipodal_classifier.so"), std::string::npos);
  result = run("run --quiet " + empty, "LD_DEBUG=files ANTIPODE_PLUGIN_LOAD=all");
  EXPECT_NE(result.out.find("libantipode_hog_svm_classifier.so"), std::string::npos);
}

TEST_F(CliTest, AnUnknownNameInALazilyLoadedTreeGetsTheFullLoadersMessage) {
  const std::string tree = write("x.yaml",
                                 "components:\n  c: { plugin: passthrough_clasifier }\n"
                                 "main: t\ntrees:\n  t:\n    AlwaysSuccess: {}\n");
  const Result result = run("validate " + tree);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.out.find("did you mean 'passthrough_classifier'?"), std::string::npos)
      << result.out;
}

TEST_F(CliTest, PluginsWriteIndexListsADirectory) {
  const fs::path plugins = dir_ / "plugins";
  fs::create_directories(plugins);
  fs::copy_file(std::string(FIXTURE_DIR) + "/good/libantipode_test_fixtures.so",
                plugins / "libantipode_test_fixtures.so");
  Result result = run("plugins --write-index " + plugins.string());
  EXPECT_EQ(result.exit_code, 0) << result.out;
  EXPECT_EQ(result.out, plugins.string() + "/antipode_plugins.index: 1 plugin library\n");
  std::ifstream in(plugins / "antipode_plugins.index");
  const std::string index((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(index.find("type CountTicks\n"), std::string::npos) << index;
  result = run("plugins --write-index " + (dir_ / "none").string());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "antipode: error: no plugin directory " + (dir_ / "none").string() + "\n");
}

TEST_F(CliTest, PluginsCheckReportsOneLibraryOrWhyItCannotLoad) {
  Result result =
      run("plugins --check " + std::string(FIXTURE_DIR) + "/good/libantipode_test_fixtures.so");
  EXPECT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("test_fixtures 1.2.3, plugin ABI "), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("provides sampler point_sampler"), std::string::npos) << result.out;
  EXPECT_EQ(result.out.find("note:"), std::string::npos) << result.out;
  // The same library under another name loads, with why a plugin directory would skip it.
  fs::copy_file(std::string(FIXTURE_DIR) + "/good/libantipode_test_fixtures.so",
                dir_ / "fixtures.so");
  result = run("plugins --check " + (dir_ / "fixtures.so").string());
  EXPECT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("note: a plugin directory loads only files named "
                            "libantipode_NAME.so; this one would be skipped there: rename it "
                            "to libantipode_test_fixtures.so"),
            std::string::npos)
      << result.out;
  const std::string broken = std::string(FIXTURE_DIR) + "/bad/libantipode_undefined_symbol.so";
  result = run("plugins --check " + broken);
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_EQ(result.out.rfind("antipode: error: " + broken + ": cannot be loaded: ", 0), 0u)
      << result.out;
  EXPECT_NE(
      result.out.find("undefined symbol: antipode::missing::function_that_does_not_exist(int)"),
      std::string::npos)
      << result.out;
  EXPECT_EQ(std::count(result.out.begin(), result.out.end(), '\n'), 1) << result.out;
  result = run("plugins --check " + std::string(FIXTURE_DIR) + "/bad/libantipode_wrong_abi.so");
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("ABI"), std::string::npos) << result.out;
}

TEST_F(CliTest, PluginsListsLoadedAndRefusedLibrariesWithReasons) {
  const Result result = run("plugins", "ANTIPODE_PLUGIN_PATH=" + std::string(FIXTURE_DIR) +
                                           "/good:" + std::string(FIXTURE_DIR) + "/bad");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.out.find("test_fixtures 1.2.3"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("provides node CountTicks"), std::string::npos);
  EXPECT_NE(result.out.find("but this antipode provides ABI"), std::string::npos);
  EXPECT_NE(
      result.out.find("undefined symbol: antipode::missing::function_that_does_not_exist(int) "
                      "[_ZN8antipode7missing28function_that_does_not_existEi]"),
      std::string::npos);
  EXPECT_NE(result.out.find("type 'point_sampler' is already provided by"), std::string::npos);
}

// Detection on real data, through trees/detect.yaml and the build tree's plugins.
class DetectTest : public CliTest {
 protected:
  const std::string krylon_ = std::string(ANTIPODE_TEST_DATA_DIR) + "/clouds/krylon.pcd";
  const std::string tree_ = std::string(ANTIPODE_TEST_SOURCE_DIR) + "/trees/detect.yaml";
  std::string detect(const std::string& cloud, const std::string& extra = "") {
    return "detect " + cloud + " --tree " + tree_ + " --out " + (dir_ / "g.json").string() +
           " --image " + (dir_ / "g.png").string() + " " + extra;
  }
  bool wrote_nothing() const {
    return !fs::exists(dir_ / "g.json") && !fs::exists(dir_ / "g.png") &&
           std::distance(fs::directory_iterator(dir_), fs::directory_iterator()) == 0;
  }
};

TEST_F(DetectTest, WritesGraspsAndPicture) {
  if (!fs::exists(krylon_)) GTEST_SKIP() << "no " << krylon_ << " (../shared/data is absent)";
  const Result result = run(detect(krylon_, "--set sampler.samples=200"));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  std::ifstream in(dir_ / "g.json");
  const auto document = nlohmann::json::parse(in);
  EXPECT_EQ(document["frame"], "sensor");
  ASSERT_GT(document["count"].get<int>(), 0);
  const auto& hand = document["hands"][0];
  for (const char* key :
       {"position_m", "quaternion_xyzw", "approach", "closing", "axis", "width_m", "score"}) {
    EXPECT_TRUE(hand.contains(key)) << key;
  }
  std::ifstream png(dir_ / "g.png", std::ios::binary);
  char magic[4] = {};
  png.read(magic, 4);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
}

// Bad camera poses and workspaces are one error line and exit 2, before any work.
TEST_F(DetectTest, BadCameraPosesAndWorkspacesAreOneLineErrors) {
  if (!fs::exists(krylon_)) GTEST_SKIP() << "no " << krylon_ << " (../shared/data is absent)";
  const std::string unknown_key = write(
      "bad.yaml", "translation_m: [0, 0, 1]\nquaternion_wxyz: [1, 0, 0, 0]\nrpy: [0, 0, 0]\n");
  const std::string short_list =
      write("short.yaml", "translation_m: [0, 1]\nquaternion_wxyz: [1, 0, 0, 0]\n");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--camera-pose '0 0 1 2 0 0 0'", "has norm 2.000000; it must be 1"},
      {"--camera-pose '0 0 1 1 0 0'", "--camera-pose takes 'x y z qw qx qy qz'"},
      {"--camera-pose nowhere.yaml", "--camera-pose: no such extrinsics file: nowhere.yaml"},
      {"--camera-pose " + unknown_key, "unknown key 'rpy'"},
      {"--camera-pose " + short_list, "'translation_m' must have 3 numbers, got 2"},
      {"--workspace 0 0 0 1 -1 1", "--workspace: the minimum y must be below the maximum"},
  };
  for (const auto& [options, message] : cases) {
    const Result result = run(detect(krylon_, options));
    EXPECT_EQ(result.exit_code, 2) << options << "\n" << result.out;
    EXPECT_NE(result.out.find(message), std::string::npos) << options << "\n" << result.out;
    EXPECT_EQ(std::count(result.out.begin(), result.out.end(), '\n'), 1) << result.out;
    EXPECT_FALSE(fs::exists(dir_ / "g.json")) << options;
  }
}

// --explain on the table-top cloud: the table is the support, the mug the one object, and
// the best grasps are on it.
TEST_F(DetectTest, ExplainNamesTheSupportTheObjectsAndWhereTheBestGraspsLie) {
  const std::string mug = std::string(ANTIPODE_TEST_DATA_DIR) + "/clouds/table_mug.pcd";
  if (!fs::exists(mug)) GTEST_SKIP() << "no " << mug << " (../shared/data is absent)";
  const Result result = run(detect(mug, "--explain --set sampler.samples=1000"));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("scene: support plane"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find(", 1 object: #0: "), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("hypotheses: "), std::string::npos) << result.out;
  // The mug's wall and rim are thinner than the closed gripper: the screen drops those hands.
  const std::regex screen(
      "left to classify by the selector's screen: [0-9]+ \\([0-9]+ at the "
      "aperture limits");
  EXPECT_TRUE(std::regex_search(result.out, screen)) << result.out;
  // The classifier's rejections are added to the screen's.
  const std::regex rejected(
      "rejected by the screen or the classifier: [0-9, a-z]*[0-9]+ low score");
  EXPECT_TRUE(std::regex_search(result.out, rejected)) << result.out;
  EXPECT_NE(result.out.find("the 12 best grasps: 12 on objects"), std::string::npos) << result.out;
  // It points to the page that shows every hand and why each was dropped.
  EXPECT_NE(result.out.find("see every hand in 3D: add --rejected, then antipode view " + mug +
                            " " + (dir_ / "g.json").string() + " --open"),
            std::string::npos)
      << result.out;
  std::ifstream in(dir_ / "g.json");
  const auto document = nlohmann::json::parse(in);
  for (const auto& hand : document["hands"]) EXPECT_EQ(hand["object"], 0);
}

// With a selection (--top), every count printed agrees: the log's classified hands with
// --explain's, and the selected grasps of the log, --explain, the file and the picture.
TEST_F(DetectTest, EveryCountOfASelectionAgrees) {
  const std::string mug = std::string(ANTIPODE_TEST_DATA_DIR) + "/clouds/table_mug.pcd";
  if (!fs::exists(mug)) GTEST_SKIP() << "no " << mug << " (../shared/data is absent)";
  const Result result = run(detect(mug, "--explain --top 3 --set sampler.samples=1000"));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(result.out, m, std::regex("([0-9]+) of [0-9]+ hands classified")))
      << result.out;
  const std::string classified = m[1];
  EXPECT_NE(result.out.find("classified as grasps: " + classified + " "), std::string::npos)
      << result.out;
  ASSERT_TRUE(std::regex_search(result.out, m, std::regex("([0-9]+) grasps selected")))
      << result.out;
  const int selected = std::stoi(m[1]);
  ASSERT_GT(selected, 0);
  EXPECT_LE(selected, 3);
  const std::string n = std::to_string(selected);
  EXPECT_NE(result.out.find("the " + n + " selected grasps: " + n + " on objects"),
            std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("picture of " + n + " hands written"), std::string::npos) << result.out;
  std::ifstream in(dir_ / "g.json");
  EXPECT_EQ(nlohmann::json::parse(in)["count"].get<int>(), selected);
}

// A model trained for another gripper is a load error (exit 2) before any sampling, naming
// both components and the command that trains a model for the gripper; nothing is written.
TEST_F(DetectTest, AModelForAnotherGripperIsALoadErrorThatNamesTheFix) {
  if (!fs::exists(krylon_)) GTEST_SKIP() << "no " << krylon_ << " (../shared/data is absent)";
  const std::string gripper =
      std::string(ANTIPODE_TEST_SOURCE_DIR) + "/robots/grippers/parallel_8cm.yaml";
  const Result result = run(detect(krylon_, "--set sampler.hand=" + gripper));
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("component 'classifier' (hog_svm_classifier) cannot score the hands "
                            "of component 'sampler' (antipodal_sampler): model "),
            std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("antipode train --out my.model --set sampler.hand=GRIPPER.yaml"),
            std::string::npos)
      << result.out;
  EXPECT_EQ(result.out.find("hand hypotheses"), std::string::npos) << "it sampled:\n" << result.out;
  EXPECT_EQ(std::count(result.out.begin(), result.out.end(), '\n'), 1) << result.out;
  EXPECT_TRUE(wrote_nothing());
}

// OpenBLAS picks its matrix kernel for the CPU it runs on; the SVM's decision values, and so
// the grasps, must not depend on which (OPENBLAS_CORETYPE forces a kernel: the SSE one of
// 2008 and, where the CPU has them, the AVX2 and FMA one).
TEST_F(DetectTest, TheSameGraspsWhicheverMatrixKernelTheCpuGets) {
  const std::string mug = std::string(ANTIPODE_TEST_DATA_DIR) + "/clouds/table_mug.pcd";
  if (!fs::exists(mug)) GTEST_SKIP() << "no " << mug << " (../shared/data is absent)";
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma"))
    GTEST_SKIP() << "this CPU has no AVX2 and FMA kernel to compare with";
  std::map<std::string, std::string> grasps;
  for (const char* core : {"Nehalem", "Haswell"}) {
    const std::string out = (dir_ / (std::string(core) + ".json")).string();
    const Result result = run("detect " + mug + " --tree " + tree_ + " --out " + out +
                                  " --set sampler.samples=1000 --set selector.max_grasps=100",
                              "OPENBLAS_CORETYPE=" + std::string(core));
    ASSERT_EQ(result.exit_code, 0) << result.out;
    std::ifstream in(out);
    grasps[core] = std::string(std::istreambuf_iterator<char>(in), {});
  }
  ASSERT_NE(grasps["Nehalem"].find("\"score\""), std::string::npos);
  EXPECT_EQ(grasps["Nehalem"], grasps["Haswell"]);
}

// A single object without a table: no support surface, the whole cloud is searched.
TEST_F(DetectTest, ExplainSaysWhenThereIsNoSupport) {
  if (!fs::exists(krylon_)) GTEST_SKIP() << "no " << krylon_ << " (../shared/data is absent)";
  const Result result = run(detect(krylon_, "--explain --set sampler.samples=300"));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("scene: no support surface: the whole cloud is used"),
            std::string::npos)
      << result.out;
}

TEST_F(DetectTest, TruncatedCloudIsOneLineErrorAndNoOutput) {
  if (!fs::exists(krylon_)) GTEST_SKIP() << "no " << krylon_ << " (../shared/data is absent)";
  std::ifstream in(krylon_, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  const std::string cloud = write("cut.pcd", bytes.substr(0, bytes.size() / 2));
  const Result result = run(detect(cloud));
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_EQ(result.out.rfind("antipode: error: ", 0), 0u) << result.out;
  EXPECT_EQ(std::count(result.out.begin(), result.out.end(), '\n'), 1) << result.out;
  fs::remove(cloud);
  EXPECT_TRUE(wrote_nothing());
}

TEST_F(DetectTest, NanOnlyAndEmptyCloudsAreErrors) {
  const std::string header =
      "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 1\n"
      "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 2\nDATA ascii\n";
  const std::string nan_cloud = write("nan.pcd", header + "nan nan nan\nnan 1 2\n");
  Result result = run(detect(nan_cloud));
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("finite"), std::string::npos) << result.out;
  fs::remove(nan_cloud);
  EXPECT_TRUE(wrote_nothing());
  const std::string empty = write("empty.pcd", "");
  result = run(detect(empty));
  EXPECT_EQ(result.exit_code, 2) << result.out;
  fs::remove(empty);
  EXPECT_TRUE(wrote_nothing());
}

// A failed detection ends with the node that failed, where it is in the tree, and why; a
// cloud in millimetres is named as the likely cause.
TEST_F(DetectTest, ACloudInMillimetresFailsWithTheNodeAndTheUnits) {
  std::string points;
  for (int x = 0; x <= 30; ++x)
    for (int y = 0; y <= 30; ++y)
      points += std::to_string(x * 20 - 300) + " " + std::to_string(y * 20 - 300) + " 600\n";
  const std::string cloud =
      write("mm.pcd",
            "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 961\n"
            "HEIGHT 1\nPOINTS 961\nDATA ascii\n" +
                points);
  const Result result = run(detect(cloud));
  EXPECT_EQ(result.exit_code, 1) << result.out;
  EXPECT_NE(result.out.find(": FAILURE (SampleHands at " + tree_ + ":"), std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("the cloud is 600 m across"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("millimetres"), std::string::npos) << result.out;
  fs::remove(cloud);
  EXPECT_TRUE(wrote_nothing());
}

// Output paths are checked before the work: a bad --image writes no --out file either.
TEST_F(DetectTest, ABadOutputPathIsAnErrorBeforeAnythingIsWritten) {
  const Result result = run("detect " + krylon_ + " --tree " + tree_ + " --out " +
                            (dir_ / "g.json").string() + " --image /no/such/folder/g.png");
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("directory '/no/such/folder' does not exist"), std::string::npos)
      << result.out;
  EXPECT_EQ(result.out.find("points loaded"), std::string::npos) << "checked before loading";
  EXPECT_TRUE(wrote_nothing());
}

TEST_F(DetectTest, WorkspaceOutsideTheCloudIsAnError) {
  if (!fs::exists(krylon_)) GTEST_SKIP() << "no " << krylon_ << " (../shared/data is absent)";
  const Result result =
      run(detect(krylon_, "--set 'sampler.workspace={min: [5, 5, 5], max: [6, 6, 6]}'"));
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("workspace"), std::string::npos) << result.out;
  EXPECT_TRUE(wrote_nothing());
}

// A bad parameter given with --set is located at --set, not at the tree file's line that
// holds the value it replaced.
TEST_F(DetectTest, BadParametersFromTheCommandLineAreLocatedAtSet) {
  Result result = run(detect(krylon_, "--set sampler.samples=abc"));
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("error: --set: parameter 'samples' of component 'sampler' must be an "
                            "integer, got 'abc'"),
            std::string::npos)
      << result.out;
  result = run(detect(krylon_, "--set sampler.sampels=100"));
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("error: --set: unknown parameter 'sampels' of component 'sampler' "
                            "(did you mean 'samples'?)"),
            std::string::npos)
      << result.out;
  EXPECT_TRUE(wrote_nothing());
}

TEST_F(CliTest, SceneDrawsTheSimulatedCellAndChecksGraspFrames) {
  const std::string source = ANTIPODE_TEST_SOURCE_DIR;
  const std::string image = (dir_ / "scene.png").string();
  const std::string common = "scene " + source + "/scenes/isolated_cylinder.yaml --tree " + source +
                             "/trees/scene.yaml --image " + image;
  Result result = run(common);
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_TRUE(fs::exists(image));
  fs::remove(image);
  // Grasps detected in a sensor frame cannot be drawn into the cell's base frame.
  const std::string grasps = write("g.json", R"({"frame": "sensor", "count": 0, "hands": []})");
  result = run(common + " --grasps " + grasps);
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("are in frame 'sensor', the cloud is in frame 'base'"),
            std::string::npos)
      << result.out;
  EXPECT_FALSE(fs::exists(image));
}

TEST_F(CliTest, VersionAndHelp) {
  EXPECT_EQ(run("--version").out.rfind("antipode ", 0), 0u);
  const Result help = run("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("Exit codes"), std::string::npos);
  EXPECT_EQ(run("frobnicate").exit_code, 2);
}

}  // namespace

// `antipode train` and `eval-classifier` on a few scenes of the simulated cell.
class TrainTest : public CliTest {
 protected:
  std::string tiny_tree() {
    const std::string source = ANTIPODE_TEST_SOURCE_DIR;
    return write(
        "tiny_train.yaml",
        "components:\n"
        "  cell: { plugin: bullet_cell, scene: " +
            source +
            "/scenes/train_procedural.yaml }\n"
            "  sampler: { plugin: antipodal_sampler, samples: 300, threads: 2 }\n"
            "main: train\n"
            "trees:\n"
            "  train:\n"
            "    Sequence:\n"
            "      - NewTrainingSet: { dataset: \"{dataset}\" }\n"
            "      - Repeat:\n"
            "          num_cycles: 4\n"
            "          progress: scenes\n"
            "          child:\n"
            "            Sequence:\n"
            "              - ResetScene: { cell: cell, first_seed: 2, seed: \"{seed}\" }\n"
            "              - CaptureCloud: { cell: cell, views: [left, right], cloud: "
            "\"{cloud}\" }\n"
            "              - ForceSuccess:\n"
            "                  child:\n"
            "                    Sequence:\n"
            "                      - SampleHands: { sampler: sampler, cloud: \"{cloud}\", "
            "hands: \"{hands}\" }\n"
            "                      - LabelHands: { hands: \"{hands}\", labelled: "
            "\"{labelled}\" }\n"
            "                      - CollectExamples: { hands: \"{labelled}\", dataset: "
            "\"{dataset}\", max_hands_per_label: 20, source: \"{seed}\" }\n"
            "      - SaveTrainingSet: { dataset: \"{dataset}\", file: \"{dataset_file}\" }\n"
            "      - TrainClassifier: { dataset: \"{dataset}\", model_file: "
            "\"{model_file}\", c_values: [1], components: 16, folds: 2 }\n");
  }
  static std::string bytes_of(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
  }
};

TEST_F(TrainTest, SameSeedSameModelAndTheModelEvaluates) {
  const std::string tree = tiny_tree();
  const std::string a = (dir_ / "a.model").string(), b = (dir_ / "b.model").string();
  const std::string data = (dir_ / "a.data").string();
  Result result = run("train --tree " + tree + " --out " + a + " --dataset " + data);
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("cross-validation accuracy"), std::string::npos) << result.out;
  result = run("train --tree " + tree + " --out " + b);
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_EQ(bytes_of(a), bytes_of(b));
  EXPECT_FALSE(fs::exists(dir_ / "b.data"));
  result = run("train --tree " + tree + " --out " + b + " --seed 1");
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(bytes_of(a), bytes_of(b));

  // The model measured on the examples it was trained on, through a tree of one node.
  const std::string eval = write("eval.yaml",
                                 "main: e\n"
                                 "trees:\n"
                                 "  e:\n"
                                 "    Sequence:\n"
                                 "      - LoadTrainingSet: { file: " +
                                     data +
                                     ", dataset: \"{d}\" }\n"
                                     "      - EvaluateClassifier: { model_file: \"{model_file}\", "
                                     "dataset: \"{d}\", report_file: \"{report_file}\" }\n");
  const fs::path report = dir_ / "report.json";
  result = run("eval-classifier --tree " + eval + " --model " + a + " --report " + report.string());
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("classified grasp"), std::string::npos) << result.out;
  std::ifstream in(report);
  const auto numbers = nlohmann::json::parse(in);
  const auto& c = numbers["confusion"];
  EXPECT_EQ(c["tp"].get<int>() + c["fp"].get<int>() + c["tn"].get<int>() + c["fn"].get<int>(),
            numbers["examples"].get<int>());
  EXPECT_GT(numbers["accuracy"].get<double>(), 0.8);  // its own training data

  // Folds the training set cannot make are refused at the folds_by port.
  const auto retrain = [&](const std::string& ports) {
    return write("retrain.yaml",
                 "main: r\n"
                 "trees:\n"
                 "  r:\n"
                 "    Sequence:\n"
                 "      - LoadTrainingSet: { file: " +
                     data +
                     ", dataset: \"{d}\" }\n"
                     "      - TrainClassifier: { dataset: \"{d}\", model_file: " +
                     b + ", c_values: [1], " + ports + " }\n");
  };
  // A model over its size budget is written, with a warning that says why it is large.
  result = run("run -q " + retrain("folds: 0, size_budget_kib: 1"));
  EXPECT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find(" KiB, over the 1 KiB budget (size_budget_kib); "), std::string::npos)
      << result.out;
  result = run("run -q " + retrain("folds: 0"));
  EXPECT_EQ(result.out.find("budget"), std::string::npos) << result.out;
  result = run("run " + retrain("folds_by: object"));
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("folds by 'object': expected example, hand or scene"),
            std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("retrain.yaml:6:"), std::string::npos) << result.out;  // located
  result = run("run " + retrain("kernels: [poly, gauss]"));
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("unknown kernel 'gauss' (use poly or rbf)"), std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("retrain.yaml:6:"), std::string::npos) << result.out;
  result = run("run " + retrain("cache_mib: 0"));
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("cache_mib must be at least 1"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("retrain.yaml:6:"), std::string::npos) << result.out;
  result = run("run " + retrain("positive_weight: -1"));
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("positive_weight must be positive"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("retrain.yaml:6:"), std::string::npos) << result.out;
  result = run("run " + retrain("kernels: []"));
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("retrain.yaml:6:"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("no kernel named (use poly, rbf or both)"), std::string::npos)
      << result.out;
  // The Gaussian kernel trains, and the model says which kernel it has.
  result = run("run " + retrain("folds: 0, kernels: [rbf]"));
  EXPECT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("rbf kernel, C = 1"), std::string::npos) << result.out;
  EXPECT_EQ(antipode::SvmModel::load(b).kernel.type, antipode::SvmKernelType::kRbf);
  result = run("run " + retrain("folds: 10, folds_by: scene"));
  EXPECT_NE(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("10 folds need at least 10 scenes (distinct sources), the training "
                            "set has 4; give CollectExamples a different `source` per scene"),
            std::string::npos)
      << result.out;

  // CrossValidate reads the same solver ports, located the same way.
  const auto cross_validate = [&](const std::string& ports) {
    return write("cv.yaml",
                 "main: c\n"
                 "trees:\n"
                 "  c:\n"
                 "    Sequence:\n"
                 "      - LoadTrainingSet: { file: " +
                     data +
                     ", dataset: \"{d}\" }\n"
                     "      - CrossValidate: { dataset: \"{d}\", components: 16, " +
                     ports + " }\n");
  };
  result = run("run " + cross_validate("folds: 2, folds_by: hand, c_values: [1, 10]"));
  EXPECT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("2-fold by hand, poly kernel, C 1, gamma "), std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("2-fold by hand, poly kernel, C 10, gamma "), std::string::npos)
      << result.out;
  for (const auto& [ports, message] : std::vector<std::pair<std::string, std::string>>{
           {"folds: 0", "folds must be at least 2 to cross-validate"},
           {"folds: 1", "folds must be 0 (no cross-validation) or at least 2"},
           {"c_values: [1, 0]", "every C must be positive"},
           {"c_values: []", "c_values is empty; give at least one C"},
           {"gamma_values: [-1]", "every gamma must be positive"},
           {"degree: 11", "degree must be in [1, 10]"},
           {"threads: -1", "threads must be 0 (all cores) or more"},
           {"positive_weight: 0", "positive_weight must be positive"}}) {
    result = run("run " + cross_validate(ports));
    EXPECT_EQ(result.exit_code, 2) << ports << ": " << result.out;
    EXPECT_NE(result.out.find(message), std::string::npos) << ports << ": " << result.out;
    EXPECT_NE(result.out.find("cv.yaml:6:"), std::string::npos) << ports << ": " << result.out;
  }
}

// Hands found in one view: LabelHands' `judged` set (closing points in the registered cloud)
// gives C1, C2 and C12 descriptors, its `labelled` set (their own one-view cloud) only one.
TEST_F(TrainTest, OneViewHandsJudgedInTheRegisteredCloudGiveThreeExamples) {
  const std::string source = ANTIPODE_TEST_SOURCE_DIR;
  const auto tree = [&](const std::string& name, const std::string& hands,
                        const std::string& describe) {
    return write(
        name,
        "components:\n"
        "  cell: { plugin: bullet_cell, scene: " +
            source +
            "/scenes/train_procedural.yaml }\n"
            "  sampler: { plugin: antipodal_sampler, samples: 300, threads: 2 }\n"
            "main: t\n"
            "trees:\n"
            "  t:\n"
            "    Sequence:\n"
            "      - NewTrainingSet: { dataset: \"{d}\" }\n"
            "      - ResetScene: { cell: cell, first_seed: 2 }\n"
            "      - CaptureCloud: { cell: cell, views: [left, right], cloud: \"{both}\" }\n"
            "      - SelectViews: { cloud: \"{both}\", views: [0], selected: \"{one}\" }\n"
            "      - SampleHands: { sampler: sampler, cloud: \"{one}\", hands: \"{h}\" }\n"
            "      - LabelHands: { hands: \"{h}\", reference: \"{both}\", labelled: \"{l}\", "
            "judged: \"{j}\" }\n"
            "      - CollectExamples: { hands: \"" +
            hands + "\", dataset: \"{d}\", max_hands_per_label: 5, " + describe +
            " }\n"
            "      - SaveTrainingSet: { dataset: \"{d}\", file: \"{dataset_file}\" }\n");
  };
  const auto examples_per_hand = [&](const std::string& file) {
    std::map<int, int> count;
    for (const int group : antipode::load_training_set(file).groups) ++count[group];
    std::vector<int> sizes;
    for (const auto& [group, n] : count) sizes.push_back(n);
    return sizes;
  };
  const std::string three = (dir_ / "three.data").string(), one = (dir_ / "one.data").string();
  Result result =
      run("run -q " + tree("three.yaml", "{j}", "single_views: [0, 1], all_views: true") +
          " --set dataset_file=" + three);
  ASSERT_EQ(result.exit_code, 0) << result.out;
  result = run("run -q " + tree("one.yaml", "{l}", "single_views: [], all_views: true") +
               " --set dataset_file=" + one);
  ASSERT_EQ(result.exit_code, 0) << result.out;
  const std::vector<int> described = examples_per_hand(three), own = examples_per_hand(one);
  ASSERT_FALSE(own.empty());
  EXPECT_GE(described.size(), own.size());  // the same hands, and some with < 10 points in one view
  for (const int n : own) EXPECT_EQ(n, 1);
  EXPECT_GT(std::count(described.begin(), described.end(), 3), 0);
  for (const int n : described) EXPECT_GE(n, 1);
}

TEST_F(TrainTest, ACorruptedModelIsOneLineErrorAtItsKey) {
  const std::string model = write("bad.model", "ANTPSVM1 but not a model at all");
  const std::string tree = write("t.yaml",
                                 "components:\n"
                                 "  classifier: { plugin: hog_svm_classifier, model: " +
                                     model +
                                     " }\n"
                                     "main: t\n"
                                     "trees:\n"
                                     "  t: { AlwaysSuccess: {} }\n");
  const Result result = run("run -q " + tree);
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_EQ(result.out.rfind("antipode: error: " + tree + ":2:", 0), 0u) << result.out;
  EXPECT_NE(result.out.find("classifier model file"), std::string::npos) << result.out;
  EXPECT_EQ(std::count(result.out.begin(), result.out.end(), '\n'), 1) << result.out;
}
