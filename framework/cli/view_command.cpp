// `antipode view`: writes the page and, with --open, hands it to the desktop's browser.
#include <spawn.h>
#include <sys/wait.h>

#include <fstream>
#include <iostream>
#include <sstream>

#include "antipode/core/atomic_file.hpp"
#include "antipode/core/error.hpp"
#include "commands.hpp"
#include "view_page.hpp"

extern char** environ;

namespace antipode::cli {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("view: cannot read the viewer page '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Starts `xdg-open page` and waits for it (it returns once the browser has the page).
void open_in_browser(const std::string& page) {
  const char* argv[] = {"xdg-open", page.c_str(), nullptr};
  pid_t pid = 0;
  if (posix_spawnp(&pid, "xdg-open", nullptr, nullptr, const_cast<char* const*>(argv), environ) !=
      0)
    throw Error("view: --open needs xdg-open (xdg-utils); the page is written: open " + page +
                " in a browser");
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw Error("view: xdg-open could not open " + page + "; open it in a browser");
}

}  // namespace

int view_command(const ViewOptions& options) {
  check_output_path(options.out_path);
  const std::string page_template = read_text(viewer_template_path());
  const nlohmann::ordered_json data = view_data(options);
  const std::string page = view_page(page_template, data);
  write_file_atomically(options.out_path, [&](const std::string& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    out << page;
    if (!out) throw Error("view: cannot write " + options.out_path);
  });
  std::size_t points = 0, hands = 0;
  for (const auto& scene : data["scenes"]) {
    if (scene.contains("cloud")) points += scene["cloud"]["count"].get<std::size_t>();
    if (scene.contains("hands")) hands += scene["hands"]["count"].get<std::size_t>();
  }
  std::cout << "view: " << options.out_path << " (" << data["scenes"].size() << " scene(s), "
            << points << " points, " << hands << " hands";
  if (data.contains("trace"))
    std::cout << ", " << data["trace"]["events"].size() << " status changes";
  std::cout << ", " << page.size() / 1024 << " KiB)\n";
  if (options.open) open_in_browser(options.out_path);
  return kExitSuccess;
}

}  // namespace antipode::cli
