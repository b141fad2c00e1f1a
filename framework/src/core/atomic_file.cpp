#include "antipode/core/atomic_file.hpp"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <mutex>

#include "antipode/core/error.hpp"

namespace antipode {
namespace fs = std::filesystem;
namespace {

// Temporary files being written, removed by the SIGINT / SIGTERM handler before the process
// ends (unlink is async-signal-safe; the slots are plain arrays claimed with atomics).
constexpr std::size_t kSlots = 16;
struct PendingSlot {
  std::atomic<bool> used{false};
  std::atomic<bool> ready{false};
  char path[4096] = {};
};
std::array<PendingSlot, kSlots> g_pending;

extern "C" void remove_pending_and_reraise(int signal_number) {
  for (PendingSlot& slot : g_pending)
    if (slot.ready.load()) ::unlink(slot.path);
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

void install_handlers_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int signal_number : {SIGINT, SIGTERM}) {
      struct sigaction current {};
      // Only where nobody else handles the signal: a host program's handler stays.
      if (::sigaction(signal_number, nullptr, &current) == 0 && current.sa_handler == SIG_DFL)
        ::signal(signal_number, remove_pending_and_reraise);
    }
  });
}

// Registers `path` for removal on SIGINT / SIGTERM while it exists; kSlots at once at most
// (beyond that a file is simply not registered).
class PendingFile {
 public:
  explicit PendingFile(const std::string& path) {
    install_handlers_once();
    if (path.size() >= sizeof(PendingSlot::path)) return;
    for (PendingSlot& slot : g_pending) {
      bool expected = false;
      if (!slot.used.compare_exchange_strong(expected, true)) continue;
      std::memcpy(slot.path, path.c_str(), path.size() + 1);
      slot.ready.store(true);
      slot_ = &slot;
      return;
    }
  }
  ~PendingFile() {
    if (slot_ == nullptr) return;
    slot_->ready.store(false);
    slot_->used.store(false);
  }
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;

 private:
  PendingSlot* slot_ = nullptr;
};

// Removes temporary files `prefix`PID`extension` in `directory` left by processes that no
// longer run (killed before they could clean up).
void sweep_stale(const fs::path& directory, const std::string& prefix,
                 const std::string& extension) {
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(directory, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0 || name.size() <= prefix.size() + extension.size() ||
        name.compare(name.size() - extension.size(), extension.size(), extension) != 0)
      continue;
    const std::string digits =
        name.substr(prefix.size(), name.size() - prefix.size() - extension.size());
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    const long pid = std::strtol(digits.c_str(), nullptr, 10);
    if (pid > 0 && pid != ::getpid() && ::kill(pid_t(pid), 0) == -1 && errno == ESRCH)
      fs::remove(entry.path(), error);
  }
}

}  // namespace

void check_output_path(const std::string& path) {
  const fs::path target(path);
  if (target.filename().empty()) throw Error("cannot write '" + path + "': not a file name");
  const fs::path directory = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(directory)) {
    throw Error("cannot write '" + path + "': directory '" + directory.string() +
                "' does not exist");
  }
  if (::access(directory.c_str(), W_OK) != 0)
    throw Error("cannot write '" + path + "': directory '" + directory.string() +
                "' is not writable");
  // The rename would replace whatever `path` names: only a regular file (or nothing) may be
  // replaced, never a device, a FIFO, a socket or a folder (`--out /dev/null` must not
  // destroy /dev/null).
  std::error_code error_code;
  const fs::file_status status = fs::status(target, error_code);
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw Error("cannot write '" + path + "': it exists and is not a regular file (" +
                (fs::is_directory(status) ? "a folder" : "a device, FIFO or socket") +
                "); give the path of a file");
}

void write_file_atomically(const std::string& path,
                           const std::function<void(const std::string&)>& write) {
  check_output_path(path);
  const fs::path target(path);
  const fs::path directory = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  // Keep the extension last: some writers (OpenCV) choose the format from it.
  const std::string prefix = "." + target.stem().string() + ".partial-";
  sweep_stale(directory, prefix, target.extension().string());
  const fs::path temporary =
      directory / (prefix + std::to_string(::getpid()) + target.extension().string());
  const PendingFile pending(temporary.string());
  try {
    write(temporary.string());
    if (!fs::exists(temporary)) throw Error("nothing was written");
    fs::rename(temporary, target);
  } catch (const std::exception& error) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw Error("cannot write '" + path + "': " + error.what());
  }
}

}  // namespace antipode
