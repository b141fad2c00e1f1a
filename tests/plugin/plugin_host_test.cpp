#include "antipode/plugin/plugin_host.hpp"

#include <dlfcn.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iterator>

#include <optional>

#include "antipode/bt/loader.hpp"
#include "antipode/bt/node_registry.hpp"
#include "antipode/core/error.hpp"
#include "antipode/interfaces/cell.hpp"
#include "antipode/interfaces/sampler.hpp"

namespace antipode {
namespace {

const std::string kGood = std::string(FIXTURE_DIR) + "/good/libantipode_test_fixtures.so";
const std::string kShadowDir = std::string(FIXTURE_DIR) + "/shadow";
const std::string kGoodDir = std::string(FIXTURE_DIR) + "/good";

std::string bad(const std::string& name) {
  return std::string(FIXTURE_DIR) + "/bad/libantipode_" + name + ".so";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

Parameters params(const std::string& yaml) {
  return Parameters(YAML::Load(yaml), "component 'c'", "t.yaml");
}

TEST(PluginHostTest, LoadsGoodPluginAndDescribesIt) {
  PluginHost host(std::vector<std::string>{});
  const PluginRecord& record = host.load_library(kGood);
  ASSERT_EQ(record.state, PluginRecord::State::kLoaded) << record.reason;
  EXPECT_EQ(record.name, "test_fixtures");
  EXPECT_EQ(record.version, "1.2.3");
  EXPECT_EQ(record.offers.size(), 11u);
  EXPECT_EQ(host.kind_of("point_sampler"), ComponentKind::kSampler);
  EXPECT_EQ(host.kind_of("line_cell"), ComponentKind::kCell);
  EXPECT_EQ(host.kind_of("CountTicks"), std::nullopt);  // a node, not a component
  EXPECT_EQ(host.kind_of("nothing"), std::nullopt);
  EXPECT_EQ(host.component_types().size(), 10u);
  EXPECT_EQ(host.node_types(), std::vector<std::string>{"CountTicks"});
}

TEST(PluginHostTest, CreatesComponentsWithTheirParameters) {
  PluginHost host(std::vector<std::string>{});
  host.load_library(kGood);
  auto cell = std::dynamic_pointer_cast<Cell>(host.create("line_cell", params("points: 4")));
  ASSERT_NE(cell, nullptr);
  EXPECT_EQ(cell->capture({"front"}).size(), 4u);
  auto sampler = std::dynamic_pointer_cast<Sampler>(host.create("point_sampler", params("")));
  ASSERT_NE(sampler, nullptr);
  EXPECT_EQ(sampler->sample(cell->capture({"front"}), RandomStream(1), {}).hands.size(), 4u);
}

TEST(PluginHostTest, FactoryErrorsReachTheCallerWithLocation) {
  PluginHost host(std::vector<std::string>{});
  host.load_library(kGood);
  try {
    host.create("line_cell", params("pionts: 4"));
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(),
                 "t.yaml:1:1: unknown parameter 'pionts' of component 'c' (did you mean "
                 "'points'?)");
  }
  try {
    host.create("line_cel", params(""));
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_TRUE(contains(error.what(),
                         "unknown component type 'line_cel' (did you mean "
                         "'line_cell'?)"))
        << error.what();
  }
}

TEST(PluginHostTest, ComponentKeepsItsLibraryLoadedAfterTheHostIsGone) {
  std::shared_ptr<Component> component;
  {
    PluginHost host(std::vector<std::string>{});
    host.load_library(kGood);
    component = host.create("line_cell", params("points: 2"));
  }
  // Calls into the plugin's code: would crash if the library had been unloaded.
  EXPECT_EQ(std::static_pointer_cast<Cell>(component)->capture({}).size(), 2u);
}

bool mapped(const std::string& path) {
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_NOLOAD);
  if (handle != nullptr) dlclose(handle);
  return handle != nullptr;
}

TEST(PluginHostTest, AnAcceptedLibraryStaysMappedAfterItsLastOwnerAndARefusedOneDoesNot) {
  {
    PluginHost host(std::vector<std::string>{});
    ASSERT_EQ(host.load_library(kGood).state, PluginRecord::State::kLoaded);
    ASSERT_EQ(host.load_library(bad("wrong_abi")).state, PluginRecord::State::kRefused);
    host.create("line_cell", params("points: 2"));
  }
  // Worker threads and thread-local destructors may still run its code after this point.
  EXPECT_TRUE(mapped(kGood));
  EXPECT_FALSE(mapped(bad("wrong_abi")));
}

TEST(PluginHostTest, MissingFileIsRefusedWithDlerrorText) {
  PluginHost host(std::vector<std::string>{});
  const std::string path = "/nonexistent/libantipode_ghost.so";
  const PluginRecord& record = host.load_library(path);
  EXPECT_EQ(record.state, PluginRecord::State::kRefused);
  EXPECT_EQ(record.path, path);
  EXPECT_TRUE(contains(record.reason,
                       "cannot open shared object file: No such file or "
                       "directory"))
      << record.reason;
}

TEST(PluginHostTest, NonLibraryFileIsRefused) {
  PluginHost host(std::vector<std::string>{});
  const PluginRecord& record = host.load_library(bad("not_elf"));
  EXPECT_EQ(record.state, PluginRecord::State::kRefused);
  EXPECT_TRUE(contains(record.reason, bad("not_elf"))) << record.reason;  // dlerror names it
}

// A real plugin library cut short (an interrupted copy): refused before dlopen maps it, with
// the reason, instead of a SIGBUS when the missing part is touched.
TEST(PluginHostTest, TruncatedLibraryIsRefusedNotMapped) {
  std::ifstream in(kGood, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  ASSERT_GT(bytes.size(), 16384u);
  const std::string path =
      ::testing::TempDir() + "libantipode_cut_" + std::to_string(::getpid()) + ".so";
  // Cut inside the loaded segments (the program headers at the start stay whole); a cut in
  // the debug sections of a build with -g alone would leave a library that loads.
  std::ofstream(path, std::ios::binary) << bytes.substr(0, 8192);
  PluginHost host(std::vector<std::string>{});
  const PluginRecord& record = host.load_library(path);
  EXPECT_EQ(record.state, PluginRecord::State::kRefused);
  EXPECT_TRUE(contains(record.reason, "the file is truncated")) << record.reason;
  std::remove(path.c_str());
}

TEST(PluginHostTest, UndefinedSymbolIsRefusedWithDlerrorText) {
  PluginHost host(std::vector<std::string>{});
  const PluginRecord& record = host.load_library(bad("undefined_symbol"));
  EXPECT_EQ(record.state, PluginRecord::State::kRefused);
  EXPECT_TRUE(contains(record.reason,
                       "undefined symbol: antipode::missing::function_that_does_not_exist(int) "
                       "[_ZN8antipode7missing28function_that_does_not_existEi]"))
      << record.reason;
}

TEST(PluginHostTest, MissingEntrySymbolIsRefused) {
  PluginHost host(std::vector<std::string>{});
  const PluginRecord& record = host.load_library(bad("no_entry"));
  EXPECT_EQ(record.state, PluginRecord::State::kRefused);
  EXPECT_TRUE(contains(record.reason, "no entry symbol 'antipode_plugin_descriptor'"))
      << record.reason;
}

TEST(PluginHostTest, WrongAbiMajorIsRefusedNamingBothVersions) {
  PluginHost host(std::vector<std::string>{});
  const PluginRecord& record = host.load_library(bad("wrong_abi"));
  EXPECT_EQ(record.state, PluginRecord::State::kRefused);
  const std::string expected = "built for plugin ABI " + std::to_string(kAbiMajor + 1) +
                               ".3, but this antipode provides ABI " + std::to_string(kAbiMajor) +
                               "." + std::to_string(kAbiMinor);
  EXPECT_TRUE(contains(record.reason, expected)) << record.reason;
  EXPECT_EQ(host.kind_of("future_sampler"), std::nullopt);
}

// The parameter checks: run without making the component, errors located as the
// factory's; a type without a check says so; a check of a type the library does not make
// refuses the library; a library built for 10.0 (no checks) still loads.
TEST(PluginHostTest, ParameterChecksRunWithoutMakingTheComponent) {
  PluginHost host(std::vector<std::string>{});
  host.load_library(kGood);
  EXPECT_TRUE(host.check("point_sampler", params("width_m: 0.04")));
  try {
    host.check("point_sampler", params("width_m: -1"));
    ADD_FAILURE() << "a negative width passed the check";
  } catch (const Error& e) {
    EXPECT_TRUE(contains(e.what(), "'width_m' must be positive")) << e.what();
    EXPECT_TRUE(contains(e.what(), "t.yaml:")) << e.what();
  }
  EXPECT_THROW(host.check("point_sampler", params("widht_m: 0.04")), Error);  // unknown key
  EXPECT_FALSE(host.check("height_classifier", params("")));
  EXPECT_THROW(host.check("no_such_type", params("")), Error);

  const PluginRecord& other = host.load_library(bad("check_of_another_type"));
  EXPECT_EQ(other.state, PluginRecord::State::kRefused);
  EXPECT_EQ(other.reason,
            "parameter check 0: 'someone_elses_sampler' is no component type of this plugin");
  const PluginRecord& older = host.load_library(bad("older_minor"));
  EXPECT_EQ(older.state, PluginRecord::State::kLoaded) << older.reason;
  EXPECT_EQ(older.abi, std::to_string(kAbiMajor) + ".0");
  EXPECT_FALSE(host.check("older_sampler", params("")));
  EXPECT_NE(host.create("older_sampler", params("")), nullptr);
}

TEST(PluginHostTest, DuplicateTypeIsRefusedNamingTheFirstLibrary) {
  PluginHost host(std::vector<std::string>{});
  host.load_library(kGood);
  const PluginRecord& record = host.load_library(bad("duplicate"));
  EXPECT_EQ(record.state, PluginRecord::State::kRefused);
  EXPECT_EQ(record.reason, "type 'point_sampler' is already provided by " + kGood);
  // The first library's factory is still the one used.
  EXPECT_NO_THROW(host.create("point_sampler", params("width_m: 0.04")));
}

TEST(PluginHostTest, UnknownKindIsRefused) {
  PluginHost host(std::vector<std::string>{});
  const PluginRecord& record = host.load_library(bad("bad_kind"));
  EXPECT_EQ(record.state, PluginRecord::State::kRefused);
  EXPECT_TRUE(contains(record.reason, "unknown kind 'gripper'")) << record.reason;
}

TEST(PluginHostTest, ComponentOfTheWrongKindIsAnError) {
  PluginHost host(std::vector<std::string>{});
  ASSERT_EQ(host.load_library(bad("wrong_created_kind")).state, PluginRecord::State::kLoaded);
  try {
    host.create("liar_classifier", params(""));
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_TRUE(contains(error.what(), "is declared as a classifier but creates a sampler"))
        << error.what();
  }
}

TEST(PluginHostTest, EarlierSearchDirectoryShadowsLaterOne) {
  PluginHost host({kShadowDir, kGoodDir, "/nonexistent-dir"});
  host.load_search_path();
  ASSERT_EQ(host.records().size(), 2u);
  EXPECT_EQ(host.records()[0].state, PluginRecord::State::kLoaded);
  EXPECT_EQ(host.records()[0].version, "0.0.1");
  EXPECT_EQ(host.records()[1].state, PluginRecord::State::kShadowed);
  EXPECT_EQ(host.records()[1].reason, "shadowed by " + host.records()[0].path);
}

TEST(PluginHostTest, SearchPathStartsWithEnvironmentDirectories) {
  setenv("ANTIPODE_PLUGIN_PATH", "/a:/b", 1);
  const auto path = PluginHost::default_search_path();
  unsetenv("ANTIPODE_PLUGIN_PATH");
  ASSERT_GE(path.size(), 4u);
  EXPECT_EQ(path[0], "/a");
  EXPECT_EQ(path[1], "/b");
  EXPECT_EQ(path[2], ANTIPODE_TEST_PLUGIN_DIR);
}

TEST(PluginHostTest, RegistersPluginNodes) {
  PluginHost host(std::vector<std::string>{});
  host.load_library(kGood);
  bt::NodeRegistry registry = bt::builtin_node_registry();
  host.register_nodes(registry);
  EXPECT_TRUE(registry.has("CountTicks"));
}

TEST(PluginHostTest, PluginNodeNamedLikeABuiltinIsRefusedAtLoad) {
  PluginHost host(std::vector<std::string>{});
  const PluginRecord& record =
      host.load_library(std::string(FIXTURE_DIR) + "/clash/libantipode_node_clash.so");
  EXPECT_EQ(record.state, PluginRecord::State::kRefused);
  EXPECT_EQ(record.reason, "node type 'Sequence' is a built-in node");
  bt::NodeRegistry registry = bt::builtin_node_registry();
  EXPECT_NO_THROW(host.register_nodes(registry));
}

TEST(PluginHostTest, TreeKeepsPluginNodeCodeLoadedAfterHostAndRegistryAreGone) {
  std::optional<bt::Tree> tree;
  {
    PluginHost host(std::vector<std::string>{});
    host.load_library(kGood);
    bt::NodeRegistry registry = bt::builtin_node_registry();
    host.register_nodes(registry);
    bt::LoadOptions options;
    options.registry = &registry;
    tree.emplace(bt::load_tree_string("main: t\ntrees:\n  t:\n    CountTicks: { count: \"{n}\" }\n",
                                      "t.yaml", options));
  }
  // Runs the plugin's node code: would crash had the library been unloaded with the host.
  EXPECT_EQ(tree->tick_once(), bt::Status::kSuccess);
  EXPECT_EQ(tree->blackboard().get<int>("n"), 1);
}

}  // namespace
}  // namespace antipode
