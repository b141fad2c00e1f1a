#pragma once
/// @file
/// Writing output files all-or-nothing, so that a failed run never leaves a half-written
/// file behind.

#include <functional>
#include <string>

namespace antipode {

/// Calls `write(temporary_path)` to produce the file, then renames the temporary file (in the
/// same directory, so the rename is atomic) to `path`. If `write` throws, or produces no
/// file, the temporary file is removed, `path` is left as it was, and an antipode::Error
/// naming `path` is thrown (the original message is kept). `path` must be absent or a regular
/// file: a folder, device, FIFO or socket there is an antipode::Error before anything is
/// written (the rename would replace it).
///
/// The temporary file is `.STEM.partial-PID.EXT` beside `path`. It is removed when the
/// process receives SIGINT or SIGTERM while writing (the handler is installed only where the
/// program has none of its own), and files of that name left by processes that no longer run
/// (killed with SIGKILL) are removed by the next write to `path`.
/// Throws the antipode::Error write_file_atomically() would throw before writing anything:
/// `path` has no file name, its directory does not exist or cannot be written to, or `path`
/// exists and is not a regular file. Commands call it for every output path before their work,
/// so that a bad path costs nothing and no other output is written.
void check_output_path(const std::string& path);

void write_file_atomically(const std::string& path,
                           const std::function<void(const std::string& temporary_path)>& write);

}  // namespace antipode
