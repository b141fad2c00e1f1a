// The plugin index and lazy loading (antipode/plugin/plugin_index.hpp, PluginHost::load_for).
#include "antipode/plugin/plugin_index.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "antipode/core/error.hpp"
#include "antipode/plugin/plugin_host.hpp"

namespace antipode {
namespace {
namespace fs = std::filesystem;

const fs::path kGood = fs::path(FIXTURE_DIR) / "good/libantipode_test_fixtures.so";
const fs::path kShadowDir = fs::path(FIXTURE_DIR) / "shadow";
const fs::path kClassifier =
    fs::path(ANTIPODE_TEST_PLUGIN_DIR) / "libantipode_passthrough_classifier.so";

// A fresh directory of its own, removed with the object.
struct TemporaryDirectory {
  fs::path path;
  explicit TemporaryDirectory(const std::string& name)
      : path(fs::temp_directory_path() /
             ("antipode-index-" + name + "-" + std::to_string(getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  TemporaryDirectory(TemporaryDirectory&& other) noexcept : path(std::move(other.path)) {
    other.path.clear();
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(TemporaryDirectory&&) = delete;
  ~TemporaryDirectory() {
    if (!path.empty()) fs::remove_all(path);
  }
  std::string str() const { return path.string(); }
};

// The fixture library (types point_sampler, ..., node CountTicks) and the passthrough
// classifier in one directory.
TemporaryDirectory two_libraries(const std::string& name) {
  TemporaryDirectory directory(name);
  fs::copy_file(kGood, directory.path / kGood.filename());
  fs::copy_file(kClassifier, directory.path / kClassifier.filename());
  return directory;
}

std::vector<std::string> loaded_files(const PluginHost& host) {
  std::vector<std::string> files;
  for (const auto& record : host.records()) {
    if (record.state == PluginRecord::State::kLoaded)
      files.push_back(fs::path(record.path).filename().string());
  }
  return files;
}

TEST(PluginIndexTest, WritesWhatEachLibraryProvides) {
  const TemporaryDirectory directory = two_libraries("write");
  EXPECT_FALSE(read_current_plugin_index(directory.str()));
  EXPECT_EQ(write_plugin_index(directory.str()), 2u);
  const auto index = read_current_plugin_index(directory.str());
  ASSERT_TRUE(index);
  ASSERT_EQ(index->libraries.size(), 2u);
  EXPECT_EQ(index->libraries[0].file, "libantipode_passthrough_classifier.so");
  EXPECT_EQ(index->libraries[0].types, std::vector<std::string>{"passthrough_classifier"});
  EXPECT_EQ(index->libraries[1].file, "libantipode_test_fixtures.so");
  EXPECT_EQ(index->libraries[1].types.size(), 11u);
  EXPECT_EQ(index->libraries[1].size_bytes, fs::file_size(kGood));
}

TEST(PluginIndexTest, AStaleOrBrokenIndexIsNotTrusted) {
  const TemporaryDirectory directory = two_libraries("stale");
  write_plugin_index(directory.str());
  // A rebuilt library (new modification time).
  const fs::path library = directory.path / kGood.filename();
  fs::last_write_time(library, fs::last_write_time(library) + std::chrono::seconds(1));
  EXPECT_FALSE(read_current_plugin_index(directory.str()));
  write_plugin_index(directory.str());
  EXPECT_TRUE(read_current_plugin_index(directory.str()));
  // A library added.
  fs::copy_file(kGood, directory.path / "libantipode_more.so");
  EXPECT_FALSE(read_current_plugin_index(directory.str()));
  fs::remove(directory.path / "libantipode_more.so");
  EXPECT_TRUE(read_current_plugin_index(directory.str()));
  // A damaged file.
  std::ofstream(directory.path / kPluginIndexFile, std::ios::app) << "lib x\n";
  EXPECT_FALSE(read_current_plugin_index(directory.str()));
}

TEST(PluginIndexTest, WritingTheIndexOfAMissingDirectoryIsAnError) {
  EXPECT_THROW(write_plugin_index("/nonexistent-plugin-dir"), Error);
}

TEST(LazyLoadingTest, OpensOnlyTheLibrariesThatProvideTheNames) {
  const TemporaryDirectory directory = two_libraries("lazy");
  write_plugin_index(directory.str());
  {
    PluginHost host({directory.str()});
    host.load_for({"point_sampler", "Sequence", "some_word"});
    EXPECT_EQ(loaded_files(host), std::vector<std::string>{"libantipode_test_fixtures.so"});
    EXPECT_EQ(host.kind_of("passthrough_classifier"), std::nullopt);
  }
  {
    PluginHost host({directory.str()});
    host.load_for({"CountTicks", "passthrough_classifier"});
    EXPECT_EQ(loaded_files(host).size(), 2u);
  }
  {
    PluginHost host({directory.str()});
    host.load_for({"Sequence", "main", "trees"});
    EXPECT_TRUE(host.records().empty());
  }
}

TEST(LazyLoadingTest, ADirectoryWithoutACurrentIndexIsLoadedWhole) {
  const TemporaryDirectory directory = two_libraries("unindexed");
  PluginHost host({directory.str()});
  host.load_for({"point_sampler"});
  EXPECT_EQ(loaded_files(host).size(), 2u);
}

TEST(LazyLoadingTest, AnEarlierDirectoryShadowsAsInAFullLoad) {
  // shadow/ (not indexed) holds a libantipode_test_fixtures.so of version 0.0.1.
  const TemporaryDirectory directory = two_libraries("shadowed");
  write_plugin_index(directory.str());
  PluginHost host({kShadowDir.string(), directory.str()});
  host.load_for({"point_sampler"});
  ASSERT_EQ(host.records().size(), 1u);
  EXPECT_EQ(host.records()[0].version, "0.0.1");
}

TEST(LazyLoadingTest, AnUnindexedDirectoryAfterAnIndexedOneLoadsEverything) {
  // The later folder's library offers the fixture's types again: loading only the
  // classifier would keep it, where a full load refuses it.
  const TemporaryDirectory indexed = two_libraries("indexed");
  write_plugin_index(indexed.str());
  const TemporaryDirectory later("later");
  fs::copy_file(kGood, later.path / "libantipode_other.so");
  PluginHost host({indexed.str(), later.str()});
  host.load_for({"passthrough_classifier"});
  ASSERT_EQ(host.records().size(), 3u);
  EXPECT_EQ(loaded_files(host).size(), 2u);  // the copy offers the fixture's types again
  EXPECT_EQ(host.records()[2].state, PluginRecord::State::kRefused);
}

TEST(LazyLoadingTest, OneTypeInTwoIndexedDirectoriesLoadsEverythingAndRefusesTheSecond) {
  const TemporaryDirectory first("first"), second("second");
  fs::copy_file(kGood, first.path / "libantipode_a.so");
  fs::copy_file(kGood, second.path / "libantipode_b.so");
  write_plugin_index(first.str());
  write_plugin_index(second.str());
  PluginHost host({first.str(), second.str()});
  host.load_for({"CountTicks"});
  ASSERT_EQ(host.records().size(), 2u);
  EXPECT_EQ(host.records()[0].state, PluginRecord::State::kLoaded);
  EXPECT_EQ(host.records()[1].state, PluginRecord::State::kRefused);
}

}  // namespace
}  // namespace antipode
