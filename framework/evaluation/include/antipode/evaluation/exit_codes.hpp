#pragma once
// Exit codes of the `antipode` command (documented in docs/cli.md); a bench's worker processes
// exit with them too (bench_processes.hpp).

namespace antipode::evaluation {

constexpr int kExitSuccess = 0;        ///< the command did what was asked; the tree succeeded
constexpr int kExitTreeFailed = 1;     ///< the tree ran and returned FAILURE
constexpr int kExitInvalidInput = 2;   ///< bad command line, tree, parameters or data file
constexpr int kExitInternalError = 3;  ///< an unexpected error inside antipode or a plugin

}  // namespace antipode::evaluation
