#include "antipode/core/atomic_file.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
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

// The rename would replace the target: a FIFO (as a device like /dev/null) or a folder there
// is refused before anything is written, and stays what it was.
TEST_F(AtomicFileTest, ATargetThatIsNotARegularFileIsRefusedAndKept) {
  const fs::path fifo = dir_ / "pipe.json", folder = dir_ / "folder.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  fs::create_directories(folder);
  for (const fs::path& target : {fifo, folder}) {
    bool wrote = false;
    try {
      write_file_atomically(target.string(), [&](const std::string& temp) {
        wrote = true;
        std::ofstream(temp) << "{}";
      });
      FAIL() << target;
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find("is not a regular file"), std::string::npos)
          << error.what();
    }
    EXPECT_FALSE(wrote);
  }
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_TRUE(fs::is_directory(folder));
  EXPECT_EQ(files(), 2u);
}

// A process killed while writing (SIGTERM) leaves no temporary file; one killed so that it
// could not clean up (its file is left behind, as after SIGKILL) has it swept by the next
// write to the same path.
TEST_F(AtomicFileTest, NoTemporaryFileOutlivesAKilledWriter) {
  const std::string path = (dir_ / "out.json").string();
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    write_file_atomically(path, [](const std::string& temp) {
      std::ofstream(temp) << "half";
      ::kill(::getpid(), SIGTERM);
      ::pause();
    });
    std::_Exit(0);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  EXPECT_EQ(files(), 0u);  // neither the file nor its temporary

  // A dead process's leftover: a pid that cannot be running (above the kernel's maximum).
  std::ofstream(dir_ / ".out.partial-99999999.json") << "left behind";
  std::ofstream(dir_ / ".other.partial-99999999.json") << "not ours to sweep";
  write_file_atomically(path, [](const std::string& temp) { std::ofstream(temp) << "{}"; });
  EXPECT_FALSE(fs::exists(dir_ / ".out.partial-99999999.json"));
  EXPECT_TRUE(fs::exists(dir_ / ".other.partial-99999999.json"));
  EXPECT_EQ(files(), 2u);
}

}  // namespace
}  // namespace antipode
