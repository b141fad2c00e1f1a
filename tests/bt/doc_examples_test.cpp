// Every C++ example in the docs and the public headers is taken from a file the build
// compiles: a fenced cpp block in docs/*.md or README.md, and an @code block in a header, is
// preceded by a line naming its file (docs/examples/*.cpp, compiled with the tests, or
// plugins/examples/..., built by the SDK test), and its lines appear there in order. A line
// "..." in an example leaves out lines of the file.
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace {
namespace fs = std::filesystem;

const fs::path kSource = ANTIPODE_TEST_SOURCE_DIR;

std::string trimmed(const std::string& line) {
  const auto first = line.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return line.substr(first, line.find_last_not_of(" \t") - first + 1);
}

// The non-blank lines of `path`, trimmed.
std::vector<std::string> code_lines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    if (!trimmed(line).empty()) lines.push_back(trimmed(line));
  return lines;
}

struct Example {
  std::string where;               ///< "docs/trees.md:354"
  std::string file;                ///< the file it is taken from ("" = not named)
  std::vector<std::string> lines;  ///< non-blank, trimmed
};

// The examples of a markdown file (fenced cpp or c++ blocks) or a header (@code blocks, their
// "///" stripped); `file` is what the line before the block names.
std::vector<Example> examples_of(const fs::path& path, bool header) {
  const std::regex opens(header ? R"(^\s*///\s*@code)" : R"(^```(cpp|c\+\+)\s*$)");
  const std::regex closes(header ? R"(^\s*///\s*@endcode)" : R"(^```\s*$)");
  const std::regex names(R"(((docs|plugins)/examples/[\w/.-]+\.cpp))");
  std::ifstream in(path);
  std::vector<Example> found;
  std::string previous;
  bool inside = false;
  int number = 0;
  for (std::string line; std::getline(in, line); previous = line) {
    ++number;
    if (!inside && std::regex_search(line, opens)) {
      inside = true;
      std::smatch file;
      found.push_back({fs::relative(path, kSource).string() + ":" + std::to_string(number),
                       std::regex_search(previous, file, names) ? file[1].str() : "",
                       {}});
    } else if (inside && std::regex_search(line, closes)) {
      inside = false;
    } else if (inside) {
      const std::string code = trimmed(header ? trimmed(line).substr(3) : line);
      if (!code.empty()) found.back().lines.push_back(code);
    }
  }
  return found;
}

// "" when the parts of `example` between "..." lines appear in `file` in order, each whole;
// else the first line not found where it should be.
std::string missing_line(const Example& example, const std::vector<std::string>& file) {
  std::size_t at = 0;  // where the next part may start in `file`
  std::vector<std::string> part;
  const auto find_part = [&]() -> bool {
    if (part.empty()) return true;
    for (std::size_t start = at; start + part.size() <= file.size(); ++start) {
      if (std::equal(part.begin(), part.end(), file.begin() + long(start))) {
        at = start + part.size();
        part.clear();
        return true;
      }
    }
    return false;
  };
  for (const std::string& line : example.lines) {
    if (line != "...") {
      part.push_back(line);
    } else if (!find_part()) {
      return part.front();
    }
  }
  return find_part() ? "" : part.front();
}

std::vector<fs::path> documents() {
  std::vector<fs::path> files = {kSource / "README.md"};
  for (const auto& entry : fs::directory_iterator(kSource / "docs"))
    if (entry.path().extension() == ".md") files.push_back(entry.path());
  return files;
}

std::vector<fs::path> headers() {
  std::vector<fs::path> files;
  for (const fs::path& root : {kSource / "framework/include", kSource / "plugins"})
    for (const auto& entry : fs::recursive_directory_iterator(root))
      if (entry.path().extension() == ".hpp" &&
          entry.path().string().find("/include/") != std::string::npos)
        files.push_back(entry.path());
  return files;
}

TEST(DocExamples, EveryExampleIsTakenFromACompiledFile) {
  int checked = 0;
  for (const bool header : {false, true}) {
    for (const fs::path& path : header ? headers() : documents()) {
      for (const Example& example : examples_of(path, header)) {
        ++checked;
        ASSERT_FALSE(example.file.empty())
            << example.where << ": the line before the example names no docs/examples/*.cpp";
        const fs::path file = kSource / example.file;
        ASSERT_TRUE(fs::is_regular_file(file)) << example.where << ": no file " << example.file;
        EXPECT_EQ(missing_line(example, code_lines(file)), "")
            << example.where << ": this line is not in " << example.file
            << " where the example has it";
      }
    }
  }
  EXPECT_GE(checked, 5);  // trees.md, robot.md, plugins.md, node.hpp, ports.hpp
}

// The check itself: a changed line is found, "..." skips lines, and the order matters.
TEST(DocExamples, AnExampleMustMatchItsFileInOrder) {
  const std::vector<std::string> file = {"int f() {", "return 1;", "}", "int g();"};
  EXPECT_EQ(missing_line({"x", "f", {"int f() {", "return 1;", "}"}}, file), "");
  EXPECT_EQ(missing_line({"x", "f", {"int f() {", "...", "int g();"}}, file), "");
  EXPECT_EQ(missing_line({"x", "f", {"int f() {", "return 2;"}}, file), "int f() {");
  EXPECT_EQ(missing_line({"x", "f", {"int g();", "...", "int f() {"}}, file), "int f() {");
}

}  // namespace
