#include "antipode/core/atomic_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "antipode/core/error.hpp"

namespace antipode {
namespace {
namespace fs = std::filesystem;

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("atomic_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::size_t files() const {
    return std::distance(fs::directory_iterator(dir_), fs::directory_iterator());
  }
  fs::path dir_;
};

TEST_F(AtomicFileTest, WritesTheFile) {
  const std::string path = (dir_ / "out.json").string();
  write_file_atomically(path, [](const std::string& temp) {
    EXPECT_EQ(fs::path(temp).extension(), ".json");
    std::ofstream(temp) << "{}";
  });
  std::ifstream in(path);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "{}");
  EXPECT_EQ(files(), 1u);
}

TEST_F(AtomicFileTest, FailedWriteLeavesNothingAndKeepsTheOldFile) {
  const std::string path = (dir_ / "out.json").string();
  std::ofstream(path) << "old";
  EXPECT_THROW(write_file_atomically(path,
                                     [](const std::string& temp) {
                                       std::ofstream(temp) << "half";
                                       throw Error("disk full");
                                     }),
               Error);
  std::ifstream in(path);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "old");
  EXPECT_EQ(files(), 1u);
}

TEST_F(AtomicFileTest, MissingDirectoryIsAnError) {
  try {
    write_file_atomically((dir_ / "no" / "out.json").string(), [](const std::string&) {});
    FAIL();
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("does not exist"), std::string::npos);
  }
}

}  // namespace
}  // namespace antipode
